// penumbra-gl surface helpers for a host's fragment shader (GLSL ES 3.00), exported as SURFACE_GLSL:
// what to write at locations 1 (normal) and 2 (material) while a renderer made with
// { normals: true } has its scene target bound. See docs/normal-maps.md.

// The world-axes unit normal of a normal-map texel (rgb, 0..1, tangent space, z out of the image).
// worldFromImage: the sprite's linear transform from image axes (x right, y down the image) to world
// axes, with its rotation, scale and mirroring. greenUp: true for OpenGL-style maps (green = up the
// image), false for DirectX-style maps. The xy part turns by the inverse transpose (exact for a
// height field), with the uniform scale taken out, so a scaled sprite keeps its relief.
vec3 penumbraWorldNormal(vec3 texel, mat2 worldFromImage, bool greenUp) {
  vec3 t = texel * 2.0 - 1.0;
  vec2 imageXY = vec2(t.x, greenUp ? -t.y : t.y);
  vec2 worldXY = inverse(transpose(worldFromImage)) * imageXY * sqrt(abs(determinant(worldFromImage)));
  return normalize(vec3(worldXY, t.z));
}

// Location 1: the normal premultiplied by the pixel's coverage (the alpha the colour is written with).
vec4 penumbraEncodeNormal(vec3 worldNormal, float coverage) {
  return vec4(worldNormal * 0.5 + 0.5, 1.0) * coverage;
}

// Location 2: specular strength 0..1, Blinn-Phong shininess 1..2048, emissive 0..1 (adds
// emissive × colour whatever the light), premultiplied by coverage.
vec4 penumbraEncodeMaterial(float specular, float shininess, float emissive, float coverage) {
  float shininessCode = log2(clamp(shininess, 1.0, exp2(PENUMBRA_SHININESS_LOG2_MAX))) / PENUMBRA_SHININESS_LOG2_MAX;
  return vec4(specular, shininessCode, emissive, 1.0) * coverage;
}
