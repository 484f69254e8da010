#version 330 core
// Plain coloured triangles (polygon fills, arrow heads), positions in world units.
layout(location = 0) in vec2 a_position;
layout(location = 1) in vec4 a_colour;   // RGBA8, normalised

uniform vec2 u_scale;
uniform vec2 u_offset;

out vec4 v_colour;

void main() {
  v_colour = a_colour;
  gl_Position = vec4(a_position * u_scale + u_offset, 0.0, 1.0);
}
