#version 300 es
// Light pass, vertex stage: stretches the unit quad over the light's world-space quad.
precision highp float;

layout(location = 0) in vec2 a_corner; // unit quad, 0..1

uniform mat4 u_viewProjection;
uniform vec2 u_quadCorner;
uniform vec2 u_quadAxisX;
uniform vec2 u_quadAxisY;

out vec2 v_world;
out vec2 v_uv;

void main() {
  v_world = u_quadCorner + a_corner.x * u_quadAxisX + a_corner.y * u_quadAxisY;
  v_uv = a_corner;
  gl_Position = u_viewProjection * vec4(v_world, 0.0, 1.0);
}
