#version 330 core
// Instanced axis-aligned rectangles (cells).
layout(location = 0) in vec2 a_corner;   // unit quad corner in [0, 1]^2
layout(location = 1) in vec4 a_box;      // min.xy, max.xy in world units
layout(location = 2) in vec4 a_colour;   // RGBA8, normalised

uniform vec2 u_scale;
uniform vec2 u_offset;

flat out vec4 v_colour;

void main() {
  vec2 p = mix(a_box.xy, a_box.zw, a_corner);
  v_colour = a_colour;
  gl_Position = vec4(p * u_scale + u_offset, 0.0, 1.0);
}
