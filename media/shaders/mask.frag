#version 330 core
// The ID pass of --masks (FaceRenderer::renderMask): every fragment of a part writes its label,
// whatever its look: tear water 1, wet trail 0.5, the rest 0 (a grey level each).
uniform float label;

out vec4 fragColour;

void main() { fragColour = vec4(label, label, label, 1.0); }
