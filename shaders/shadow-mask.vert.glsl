#version 300 es
// Shadow mask, vertex stage: turns each hull edge into a quad that covers every point the edge can
// hide any part of the light disk from. The two far corners are pushed along the outer tangents of
// the disk through the edge's end points, far beyond the light's bounds (the scissor cuts them).
// They stay finite rather than at w = 0: SwiftShader culls every triangle with a w = 0 vertex.
precision highp float;
precision highp int;
precision highp sampler2D;

// One instance per edge; the edge's number is the global number of its start point.
layout(location = 0) in uint a_edge;

// Point records: world xy, then the first point and point count of the point's hull.
uniform sampler2D u_hullPoints;
uniform mat4 u_viewProjection;
uniform vec2 u_lightPosition;
uniform float u_lightRadius;
uniform float u_projectionLength; // well beyond the light's bounds, see ShadowMaskPass

flat out ivec2 v_hull;

vec4 pointRecord(int index) {
  int width = textureSize(u_hullPoints, 0).x;
  return texelFetch(u_hullPoints, ivec2(index % width, index / width), 0);
}

void main() {
  int edge = int(a_edge);
  vec4 start = pointRecord(edge);
  ivec2 hull = ivec2(start.zw);
  vec2 end = pointRecord(hull.x + (edge - hull.x + 1) % hull.y).xy;
  // Corners in fan order: start, end, end projected, start projected.
  vec2 corner = vec2(gl_VertexID == 1 || gl_VertexID == 2 ? 1.0 : 0.0, gl_VertexID >= 2 ? 1.0 : 0.0);
  vec2 point = mix(start.xy, end, corner.x);
  vec2 other = mix(end, start.xy, corner.x);
  vec2 fromLight = point - u_lightPosition;
  float distance = max(length(fromLight), 1e-6);
  vec2 direction = fromLight / distance;
  // The outer tangent from the disk through the point leans away from the edge's other end by asin(r / d).
  float sine = min(u_lightRadius / distance, 1.0);
  float cosine = sqrt(1.0 - sine * sine);
  vec2 along = other - point;
  float away = -sign(direction.x * along.y - direction.y * along.x) * sine;
  vec2 tangent = vec2(direction.x * cosine - direction.y * away, direction.x * away + direction.y * cosine);
  gl_Position = u_viewProjection * vec4(point + tangent * (corner.y * u_projectionLength), 0.0, 1.0);
  v_hull = hull;
}
