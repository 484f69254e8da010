#version 330 core
// Soft one-pixel edges across the segment; thin lines (< 1 px) fade instead of vanishing.
in float v_across_px;
flat in float v_half_px;
flat in vec4 v_colour;
out vec4 frag_colour;

void main() {
  float coverage = clamp(max(v_half_px, 0.5) - abs(v_across_px) + 0.5, 0.0, 1.0) * min(v_half_px * 2.0, 1.0);
  if (coverage <= 0.0) discard;
  frag_colour = vec4(v_colour.rgb, v_colour.a * coverage);
}
