#version 300 es
// Light pass, vertex stage: places a light shape on the light's world-space quad and hands the
// fragment stage the pixel's world position, its offset from the light in ranges and its point of
// the quad (0..1). The light's other values are uniforms of the fragment stage (see the chunk
// light-common): no flat varyings, which ANGLE's Metal backend emulates at a cost per draw.
//
// Plain: a_corner is a point of the unit square (LightShapes), mapped onto the quad.
// TILED: a_corner is a tile's corner (column, row, corner x, corner y) of the grid over the light's
// filed bounds (see src/geometry/LightTiles.ts). The first tile of a run of one class (its code in
// the light's row of u_tileCodes, tileCode in src/geometry/shadowLayout.ts) stretches to the
// run's end; the run's other tiles, and a run of a class other than the one this draw shades,
// collapse to a point and draw nothing. Corners are the grid's corner plus whole numbers of tiles,
// the same expression in every program (`invariant`), so a light's draws meet without gaps or overlaps.
precision highp float;
invariant gl_Position;

uniform mat4 u_viewProjection;
uniform vec2 u_quad[3]; // the light's quad: a corner and the two edge vectors (Light.writeQuad)
// The light pass's light; the debug outline leaves it unset and ignores the varyings it feeds.
uniform vec3 u_light; // position xy, range

#ifdef TILED
layout(location = 0) in vec4 a_corner;
uniform vec4 u_tiles; // the grid's corner xy (least x and y), a tile's width and height
uniform vec2 u_tileDraw; // the light's row of tile classes, and the class this draw shades (TILE_CLASSES)
uniform highp sampler2D u_tileCodes;
#else
layout(location = 0) in vec2 a_corner; // unit quad, 0..1
#endif

out vec2 v_fromLight;
out vec2 v_uv;
out vec2 v_world;

void main() {
#ifdef TILED
  int tile = int(a_corner.y) * TILE_GRID + int(a_corner.x);
  float code = floor(texelFetch(u_tileCodes, ivec2(tile, int(u_tileDraw.x)), 0).r * 255.0 + 0.5);
  float tileClass = mod(code, float(TILE_CLASS_CODES)), runLength = floor(code / float(TILE_CLASS_CODES)) + 1.0;
  vec2 corner = a_corner.xy + vec2(a_corner.z * runLength, a_corner.w);
  vec2 world = u_tiles.xy + corner * u_tiles.zw;
  v_uv = inverse(mat2(u_quad[1], u_quad[2])) * (world - u_quad[0]);
  if (code >= float(TILE_IN_RUN) || tileClass != u_tileDraw.y) world = u_tiles.xy;
#else
  vec2 world = u_quad[0] + a_corner.x * u_quad[1] + a_corner.y * u_quad[2];
  v_uv = a_corner;
#endif
  v_fromLight = (world - u_light.xy) / u_light.z;
  v_world = world;
  gl_Position = u_viewProjection * vec4(world, 0.0, 1.0);
  gl_Position.z = 0.0;
}
