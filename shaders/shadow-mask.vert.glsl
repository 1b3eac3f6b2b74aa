#version 300 es
// Shadow mask, vertex stage: turns each hull edge into a quad that covers every point the edge can
// hide any part of the light disk from. The two far corners go to infinity (w = 0) along the outer
// tangents of the disk through the edge's end points; the scissor rectangle bounds them.
precision highp float;

layout(location = 0) in vec4 a_segment; // edge start (xy) and end (zw), world units
layout(location = 1) in vec2 a_corner;  // x: 0 = start, 1 = end; y: 1 = projected to infinity
layout(location = 2) in vec2 a_hull;    // first point and point count of the edge's hull

uniform mat4 u_viewProjection;
uniform vec2 u_lightPosition;
uniform float u_lightRadius;

flat out ivec2 v_hull;

void main() {
  vec2 point = mix(a_segment.xy, a_segment.zw, a_corner.x);
  vec2 other = mix(a_segment.zw, a_segment.xy, a_corner.x);
  vec2 fromLight = point - u_lightPosition;
  float distance = max(length(fromLight), 1e-6);
  vec2 direction = fromLight / distance;
  // The outer tangent from the disk through the point leans away from the edge's other end by asin(r / d).
  float sine = min(u_lightRadius / distance, 1.0);
  float cosine = sqrt(1.0 - sine * sine);
  vec2 along = other - point;
  float away = -sign(direction.x * along.y - direction.y * along.x) * sine;
  vec2 tangent = vec2(direction.x * cosine - direction.y * away, direction.x * away + direction.y * cosine);
  vec4 world = a_corner.y > 0.5 ? vec4(tangent, 0.0, 0.0) : vec4(point, 0.0, 1.0);
  gl_Position = u_viewProjection * world;
  v_hull = ivec2(a_hull);
}
