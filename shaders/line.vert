#version 330 core
// Instanced segments of a width in pixels: each instance is a quad around the segment, widened in
// screen space so lines stay crisp at every zoom.
layout(location = 0) in vec2 a_corner;   // x in {0, 1} along the segment, y in {-1, 1} across
layout(location = 1) in vec4 a_ends;     // from.xy, to.xy in world units
layout(location = 2) in vec4 a_colour;   // RGBA8, normalised
layout(location = 3) in float a_width;   // pixels

uniform vec2 u_scale;
uniform vec2 u_offset;
uniform vec2 u_viewport;

out float v_across_px;   // signed distance from the centre line, pixels
flat out float v_half_px;
flat out vec4 v_colour;

void main() {
  vec2 p0 = (a_ends.xy * u_scale + u_offset) * 0.5 * u_viewport;  // pixels from the centre
  vec2 p1 = (a_ends.zw * u_scale + u_offset) * 0.5 * u_viewport;
  vec2 dir = p1 - p0;
  float len = length(dir);
  dir = len > 1e-6 ? dir / len : vec2(1.0, 0.0);
  vec2 normal = vec2(-dir.y, dir.x);
  float half_px = 0.5 * a_width;
  float extent = half_px + 1.0;
  // Extend half a pixel past each end so joined chains have no gaps.
  vec2 p = mix(p0 - dir * 0.5, p1 + dir * 0.5, a_corner.x) + normal * a_corner.y * extent;
  v_across_px = a_corner.y * extent;
  v_half_px = half_px;
  v_colour = a_colour;
  gl_Position = vec4(p * 2.0 / u_viewport, 0.0, 1.0);
}
