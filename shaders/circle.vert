#version 330 core
// Instanced circles: one quad per instance, the circle is cut out in circle.frag.
layout(location = 0) in vec2 a_corner;    // unit quad corner in [-1, 1]^2
layout(location = 1) in vec3 a_circle;    // centre x, y and radius, world units
layout(location = 2) in vec4 a_fill;      // RGBA8, normalised
layout(location = 3) in vec4 a_outline;   // RGBA8, normalised
layout(location = 4) in vec2 a_style;     // minimum radius in pixels, outline width in pixels

uniform vec2 u_scale;     // world -> NDC: ndc = world * u_scale + u_offset
uniform vec2 u_offset;
uniform vec2 u_viewport;  // pixels

out vec2 v_local_px;             // fragment offset from the centre, pixels
flat out float v_radius_px;
flat out float v_outline_px;
flat out vec4 v_fill;
flat out vec4 v_outline;

void main() {
  float pixels_per_unit = 0.5 * u_scale.x * u_viewport.x;
  float radius_px = max(a_circle.z * pixels_per_unit, a_style.x);
  float extent = radius_px + 1.0;  // one pixel of margin for the anti-aliased edge
  v_local_px = a_corner * extent;
  v_radius_px = radius_px;
  v_outline_px = a_style.y;
  v_fill = a_fill;
  v_outline = a_outline;
  vec2 centre = a_circle.xy * u_scale + u_offset;
  gl_Position = vec4(centre + v_local_px * 2.0 / u_viewport, 0.0, 1.0);
}
