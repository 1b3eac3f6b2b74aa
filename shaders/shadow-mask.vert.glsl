#version 300 es
// Shadow mask, vertex stage: turns each hull edge into a quad that covers every point the edge can
// hide any part of the light disk from. The two far corners are pushed along the outer tangents of
// the disk through the edge's end points, far beyond the light's bounds (the scissor cuts them).
// They stay finite rather than at w = 0: SwiftShader culls every triangle with a w = 0 vertex.
precision highp float;

layout(location = 0) in vec4 a_segment; // edge start (xy) and end (zw), world units
layout(location = 1) in vec2 a_corner;  // x: 0 = start, 1 = end; y: 1 = projected to infinity
layout(location = 2) in vec2 a_hull;    // first point and point count of the edge's hull

uniform mat4 u_viewProjection;
uniform vec2 u_lightPosition;
uniform float u_lightRadius;
uniform float u_projectionLength; // well beyond the light's bounds, see ShadowMaskPass

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
  gl_Position = u_viewProjection * vec4(point + tangent * (a_corner.y * u_projectionLength), 0.0, 1.0);
  v_hull = ivec2(a_hull);
}
