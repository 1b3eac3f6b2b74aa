#version 300 es
// Light pass, vertex stage: places a light shape on the light's world-space quad and hands the
// fragment stage the pixel's world position, its offset from the light in ranges and its point of
// the quad (0..1). The light's other values are uniforms of the fragment stage (see the chunk
// light-common): no flat varyings, which ANGLE's Metal backend emulates at a cost per draw.
//
// Plain: a_corner is a point of the unit square (LightShapes), mapped onto the quad.
// TILED: a_corner is a corner point (i, j) of the tile grid over the light's filed bounds, of a
// rectangle of tiles of one class (see src/shadow/LightTiles.ts): the grid's corner plus whole
// numbers of tiles, the same expression in every program (`invariant`), so a light's draws meet
// without gaps or overlaps.
precision highp float;
invariant gl_Position;

uniform mat4 u_viewProjection;
uniform vec2 u_quad[3]; // the light's quad: a corner and the two edge vectors (Light.writeQuad)
// The light pass's light; the debug outline leaves it unset and ignores the varyings it feeds.
uniform vec3 u_light; // position xy, range

#ifdef TILED
layout(location = 0) in vec2 a_corner;
uniform vec4 u_tiles; // the grid's corner xy (least x and y), a tile's width and height
#else
layout(location = 0) in vec2 a_corner; // unit quad, 0..1
#endif

out vec2 v_fromLight;
out vec2 v_uv;
out vec2 v_world;
#ifdef TILED
out vec2 v_tile; // the point in tile units of the grid (the listed program's tile)
#endif

void main() {
#ifdef TILED
  vec2 world = u_tiles.xy + a_corner * u_tiles.zw;
  v_tile = a_corner;
  v_uv = inverse(mat2(u_quad[1], u_quad[2])) * (world - u_quad[0]);
#else
  vec2 world = u_quad[0] + a_corner.x * u_quad[1] + a_corner.y * u_quad[2];
  v_uv = a_corner;
#endif
  v_fromLight = (world - u_light.xy) / u_light.z;
  v_world = world;
  gl_Position = u_viewProjection * vec4(world, 0.0, 1.0);
  // Depth 0 whatever the matrix does to z: the near and far planes never clip a light (no light
  // draw tests depth).
  gl_Position.z = 0.0;
}
