#version 300 es
// Hull pass, vertex stage: places the hulls' triangles (world points) in clip space.
precision highp float;

layout(location = 0) in vec2 a_position;
uniform mat4 u_viewProjection;

void main() {
  gl_Position = u_viewProjection * vec4(a_position, 0.0, 1.0);
}
