#version 330 core
// Skin seen whole: its texture layers (skin.glsl) without the fine relief, which only shows
// close up (SkinDetail.h) and would cost a fifth of the frame here.
#include "common.glsl"
#include "skin.glsl"

void main() { shadeSkin(0.0); }
