// GLSL 3.30 core sources of the renderer's programs. Shading is deferred: the geometry passes
// write albedo, normal and depth only, and one full-screen pass lights every pixel once (key
// light with shadow map, ambient, ambient occlusion). Sphere impostors write gl_FragDepth, which
// turns off early depth tests on llvmpipe, so keeping their fragments cheap is what keeps a
// frame fast.
#pragma once

namespace firn::viz::shaders {

// Sphere impostors: one point sprite per exposed particle (positions and the colour scalar are
// vertex attributes read from the engine's SoA columns through an index list), ray-cast in the
// fragment shader.
extern const char* const kSphereVertex;
extern const char* const kSphereFragment;
// The shadow pass's sphere: under the light's orthographic projection a sphere's shadow is
// exactly a disc; drawn at the centre's depth without writing gl_FragDepth.
extern const char* const kSphereShadowFragment;
// Triangle meshes (ground, colliders, snow) with position and normal per vertex (and rest position
// for snow).
extern const char* const kMeshVertex;
extern const char* const kMeshFragment;
extern const char* const kDepthOnlyFragment;
// The snow surface and its hoar crystals (kMeshVertex, with each vertex's rest position): the snow
// albedo and a marker for the lighting pass's snow model; grains (cells in material coordinates)
// tilt the surface's normal, crystals get flat facet normals.
extern const char* const kSnowFragment;
// Full-screen passes (one triangle): ambient occlusion at half resolution, then lighting,
// shadows, background, tone and gamma. Both get kScreenFunctions after their #version line, and
// the lighting pass the preprocessor switches SHADOWS, AMBIENT_OCCLUSION and SUBSURFACE (0 or 1): llvmpipe
// runs both sides of a branch on a uniform under a mask, so only leaving code out saves it.
extern const char* const kCompositeVertex;
extern const char* const kScreenFunctions;
extern const char* const kOcclusionFragment;
extern const char* const kCompositeFragment;

}  // namespace firn::viz::shaders
