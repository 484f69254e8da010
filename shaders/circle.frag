#version 330 core
// Cuts the circle out of its quad: coverage from the distance to the rim (one-pixel soft edge),
// then the outline band of v_outline_px pixels inside the rim over the fill.
in vec2 v_local_px;
flat in float v_radius_px;
flat in float v_outline_px;
flat in vec4 v_fill;
flat in vec4 v_outline;
out vec4 frag_colour;

void main() {
  float d = length(v_local_px);
  float coverage = clamp(v_radius_px - d + 0.5, 0.0, 1.0);
  if (coverage <= 0.0) discard;
  float band = clamp(d - (v_radius_px - v_outline_px) + 0.5, 0.0, 1.0);
  vec4 c = mix(v_fill, v_outline, v_outline.a > 0.0 ? band : 0.0);  // no outline: fill to the rim
  frag_colour = vec4(c.rgb, c.a * coverage);
}
