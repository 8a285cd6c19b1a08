// The shape of a wet trail, shared by its two passes (trail_tint.frag darkens the skin under
// it, trail.frag adds what the water reflects).
//
// Just behind the drop the trail is a rivulet, a rounded bead of water a few millimetres wide;
// as it thins and dries it becomes a flat film and fades out. The mesh is flat on the skin; the
// bead's rounded cross-section is in the normal, tilted across the trail by the slope of a
// parabolic profile (zero in the middle, steepest at the edges):
//   n = normalize(n_skin + across * slope * d),  d the direction across the trail,
// so highlights run along the rivulet as a line of light, as on a real tear track.

in vec3 vViewPos;
in vec3 vViewNormal;
in vec3 vViewAcross;
in float vWetness;
in float vAcross;

struct TrailFilm {
  vec3 normal;      // view space, with the rounded profile
  float wet;        // 1 fresh .. 0 dry
  float rivulet;    // 1 for running water, 0 for the film it leaves
  float thickness;  // 1 in the middle .. 0 at the edges
  float body;       // how much of the water shows: soft towards the edges, never a hard line
};

TrailFilm trailFilm() {
  TrailFilm f;
  vec3 skin = normalize(vViewNormal);
  vec3 d = vViewAcross - dot(vViewAcross, skin) * skin;
  d = dot(d, d) > 1e-8 ? normalize(d) : vec3(0.0);
  float across = clamp(vAcross, -1.0, 1.0);
  f.wet = clamp(vWetness, 0.0, 1.0);
  // About the last second of a trail (it dries over ten) is still running water.
  f.rivulet = smoothstep(0.80, 0.98, f.wet);
  f.normal = normalize(skin + across * mix(0.12, 0.9, f.rivulet) * d);
  f.thickness = 1.0 - across * across;
  f.body = f.wet * (1.0 - pow(abs(across), 4.0));
  return f;
}
