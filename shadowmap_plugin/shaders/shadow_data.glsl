// Every light's shadow parameters, one std140 uniform block shared by the hook's vertex part
// (texgen.glsl) and its fragment part (visibility.glsl), filled once per frame from
// plugin/ShadowBlock.h (the same layout, static_asserted there; ShadowBlockLayoutTest checks
// it against the compiled block). SHADOW_BLOCK_BINDING and MAX_CASCADES are defined from
// ShadowBlock.h's constants (shadowBlockGlslDefines), MAX_LIGHTS from engine/render/Frame.h.
//   eyePlanes   Ee, rows s,t,r,q (2D maps)
//   params      x: 1 = reversed Z (ShadowSettings reversed_z: window depth 1 at near, 0 at
//               far, and the map compares with GL_GEQUAL); y: bias subtracted from the
//               reference depth (d32f without reversed Z, see ShadowSettings.h); z: dimming
//               (applied by the engine, hook.dimming); w: the shade outside the map (2D
//               maps) or of every point of a light without a map this frame (1 for lights
//               without shadows, 0 for a spot light whose frustum holds nothing the camera
//               sees: every visible point is outside it)
//   lightInEye  xyz: the light's eye-space position (spot, point: w 1) or the direction
//               toward it (directional: w 0); w also tells a perspective map (1) from an
//               orthographic one (0)
//   pointFar    cube maps: x: far, 0 = infinite; y: the cube lookup's texel bias,
//               kCubeTexelBias * 2 / resolution (CubeMapProjection.cpp); z: near
//   eyeToWorld  R_V in its upper 3x3: cube lookups use world axes
//   cascadePlanes  Ee of each cascade of a cascaded directional light,
//               [slot * MAX_CASCADES + cascade]
//   cascadeFar  the far view depth (distance along the camera's -Z) of cascades 0..3; the
//               largest float for cascades the light does not have
//   cascadeBlend  x: cascade_blend (the band past each split, as a fraction of the nearer
//               cascade's depth range, where the lookup fades into the next cascade; 0: none),
//               y: the near view depth of cascade 0; z: shadow_distance, the view depth from
//               which every point is lit (0: none), w: where the fade toward it starts
//   softLayers  per light and layer [slot * MAX_CASCADES + layer] (2D and cube maps: layer 0),
//               for soft filters (pcss): xy: the light's size in map coordinates per unit
//               of spread, 0.5 * P[0][0] and 0.5 * P[1][1] of the layer's projection times
//               the light radius (perspective) or tan(angular_diameter / 2) (orthographic);
//               z: near (perspective) or 0; w: far (perspective, 0 = infinite) or the depth
//               range far - near (orthographic); xy 0 for a light without a size, zw always
//               (vsm and evsm read them: moments.glsl)
//   lookupParams  x: filter_radius in texels (wide pcf); y: pcss's blocker search taps;
//               z: filter_taps; w: normal_offset in texels. vsm and evsm (their blur is in
//               the moments): x: bleed_reduction; yz: evsm_exponents
//   texelWidths   a map texel's width in eye units per unit of q (2D maps: q is the distance
//               along the light's axis for a spot light, 1 for a directional one) in x, per
//               unit of the major-axis distance for a cube in x, or per cascade in x..w;
//               a warped 2D map (lispsm, q the distance along its warp axis) also grows
//               along the warp as q^2: per unit of q^2 in y (0 for every other 2D map)
layout(std140, binding = SHADOW_BLOCK_BINDING) uniform ShadowData {
    mat4 eyePlanes[MAX_LIGHTS];
    vec4 params[MAX_LIGHTS];
    vec4 lightInEye[MAX_LIGHTS];
    vec4 pointFar[MAX_LIGHTS];
    mat4 eyeToWorld;
    mat4 cascadePlanes[MAX_LIGHTS * MAX_CASCADES];
    vec4 cascadeFar[MAX_LIGHTS];
    vec4 cascadeBlend[MAX_LIGHTS];
    vec4 softLayers[MAX_LIGHTS * MAX_CASCADES];
    vec4 lookupParams[MAX_LIGHTS];
    vec4 texelWidths[MAX_LIGHTS];
} shadowData;
