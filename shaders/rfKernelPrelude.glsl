// The GLSL side of the kernel dialect: the macros of module/core/kernel/rf_kernel_prelude.h
// mapped to GLSL 1.50, so that the kernel headers (module/core/kernel/rf_kernel_*.h, written
// once for the C core and the shaders) compile here unchanged. The build embeds this file and
// the kernel headers, in order and without their #include lines, as rfKernelSource (rfShaders.h):
// a stage's shader is its defines + rfKernelSource + the stage's own code.
//
// What the including shader provides: nothing but the arguments. No kernel function reads a
// uniform, a varying or a global; every name the kernel defines starts with rf (rfk_* kernel
// functions and structs, rf_* macros, RF_* constants), so stage code should avoid those
// prefixes with an underscore. It needs texelFetch (GLSL 1.30+) and is written for #version 150.
//
// Entry points (C twins: the public wrappers in module/core, which validate first):
//   int   rfk_refract(vec3 I, vec3 N, float eta, int tirPolicy, out vec3 T)    Snell
//         I, N unit (N either way round); eta = n_incident / n_transmitted; tirPolicy
//         RF_TIR_POLICY_CLAMP (paper, section 5) or RF_TIR_POLICY_REFLECT. Returns RF_REFRACTED
//         or RF_TOTAL_INTERNAL_REFLECTION.                                 (rf_refract[_clamped])
//   float rfk_fresnel_dielectric(float cosI, float eta)  exact dielectric Fresnel (|cosI|)
//   float rfk_fresnel_schlick(float cosI, float eta)
//   vec3  rfk_builtin_environment(vec3 directionWorld)   world space, +y up
//                                                              (rf_builtin_environment)
//   float rfk_isr_view_distance(float backDepth, vec3 P1, vec3 V)  Wyman's d_V
//   float rfk_isr_distance(float dV, float dN, vec3 V, vec3 N1, vec3 T1, float eta)
//         the DIR paper's eq. 2 (Wyman 2005a): P2 = P1 + d T1 is its eq. 1   (rf_isr_distance)
//   vec2  rf_oct_encode(vec3 n) / vec3 rf_oct_decode(vec2 e)   octahedral normals, [-1, 1]^2
//   float rfk_ssp_fresnel(float NdotV, float bias, float power)   Sousa's listing 19-3
//   vec2  rfk_ssp_perturbed(vec2 own, vec3 N, float strength, float scale)   SSP's lookup
//         position: own + N.xy strength scale (own in [0, 1]^2)
//   rfk_camera rfk_make_camera(mat4 projection, vec2 viewportSize, bool isParallel)
//         projection: view to clip as VTK's key matrix (vtkOpenGLCamera::GetKeyMatrices' vcdc,
//         uploaded as VTK does); viewportSize: the depth map's size in texels.
//   rfk_search_settings rfk_make_search_settings(int steps, bool adaptive, bool secant)
//   bool  rfk_dir_search(vec3 P1, vec3 T1, vec2 depthRange, rfk_camera camera,
//         rfk_search_settings settings, sampler2D backDepth, out vec3 P2, out vec2 tc)
//         DIR's exit search (eq. 3-10, algorithm 2, frustum clip, adaptive bound, secant):
//         P1 the entry point and T1 the unit refracted direction in view space; depthRange
//         (Zmin, Zmax) as positive depths (Zmin > Zmax: nothing captured, returns false);
//         backDepth holds positive depths (-z_view) per viewport pixel, 0 where empty, read
//         with texelFetch (level 0, never filtered). tc: P2's texture coordinates by eq. 10,
//         i.e. exactly the texel the search accepted P2 on (read the exit normal there).
//                                                                          (rf_dir_search)
//   vec2  rfk_project_to_texture(rfk_camera camera, vec3 p)   view space to [0,1]^2
//   float rfk_dir_alpha(float k1, float k2, float z)           eq. 9       (rf_dir_alpha)
//   float rfk_frustum_exit(rfk_camera camera, vec3 P, vec3 T)  the ray's exit from the frustum
//   int   rfk_peel_trace(...) / void rfk_peel_follow(...)   PEEL's ray through K depth-peeled
//         layers, every interface, a medium stack, TIR followed (rf_kernel_peel.h; needs
//         RF_PEEL_LAYERS and the stage's lookups, below)                    (rf_peel_trace)
//   float rfk_sh_basis(int l, int m, vec3 d)   real spherical harmonic Y_l^m    (rf_sh_basis)
//   float rfk_sh_evaluate(table, base, order, d)   a sum over the basis (needs RF_SH_TABLE and
//         rf_sh_coefficient from the stage)                                   (rf_sh_evaluate)
// Smaller pieces (rfk_dir_make_segment, rfk_dir_cbs, rfk_dir_secant, rfk_stored_depth, ...)
// are there for stages that need only part of the search; see rf_kernel_dir.h.
#define RF_GLSL 1
#define RF_KERNEL
#define RF_OUT(type) out type
#define RF_INOUT(type) inout type
#define RF_DEREF(name) name
#define RF_ADDR(name) name
#define RF_TRUE true
#define RF_FALSE false
#define RF_STRUCT_BEGIN(name) struct name {

#define rf_float float
#define rf_bool bool
#define rf_float2 vec2
#define rf_float3 vec3
#define rf_float4 vec4
#define rf_mat4 mat4
#define rf_depth_map sampler2D

#define rf_make2(x, y) vec2(x, y)
#define rf_make3(x, y, z) vec3(x, y, z)
#define rf_make4(x, y, z, w) vec4(x, y, z, w)
#define rf_add2(a, b) ((a) + (b))
#define rf_sub2(a, b) ((a) - (b))
#define rf_scale2(v, s) ((v) * (s))
#define rf_mul2(a, b) ((a) * (b))
#define rf_dot2(a, b) dot(a, b)
#define rf_length2(v) length(v)
#define rf_add3(a, b) ((a) + (b))
#define rf_sub3(a, b) ((a) - (b))
#define rf_scale3(v, s) ((v) * (s))
#define rf_div3(v, s) ((v) / (s))
#define rf_neg3(v) (-(v))
#define rf_dot3(a, b) dot(a, b)
#define rf_cross3(a, b) cross(a, b)
#define rf_length3(v) length(v)
#define rf_normalize3(v) normalize(v)
#define rf_mix3(a, b, t) mix(a, b, t)
#define rf_reflect3(i, n) reflect(i, n)
#define rf_mul_mat4(m, v) ((m) * (v))

#define rf_abs(x) abs(x)
#define rf_sqrt(x) sqrt(x)
#define rf_floor(x) floor(x)
#define rf_ceil(x) ceil(x)
#define rf_log2(x) log2(x)
#define rf_pow(x, y) pow(x, y)
#define rf_acos(x) acos(x)
#define rf_sin(x) sin(x)
#define rf_cos(x) cos(x)
#define rf_atan2(y, x) atan(y, x)
#define rf_isinf(x) isinf(x)
#define rf_min(a, b) min(a, b)
#define rf_max(a, b) max(a, b)
#define rf_clamp(x, lo, hi) clamp(x, lo, hi)
#define rf_fract(x) fract(x)
#define rf_mix(a, b, t) mix(a, b, t)
#define rf_smoothstep(e0, e1, x) smoothstep(e0, e1, x)
#define rf_sign_not_zero(x) ((x) < 0.0 ? -1.0 : 1.0)
#define rf_imin(a, b) min(a, b)
#define rf_int_of(x) int(x)

// The nearest texel, unfiltered (the depths must never be interpolated across the silhouette).
// The channel holding the depth: RF_DEPTH_CHANNEL when the including stage defines it
// (vtkRefractionPass keeps the back depth in alpha, beside the normal), else red.
#ifndef RF_DEPTH_CHANNEL
#define RF_DEPTH_CHANNEL r
#endif
#define rf_sample_depth(map, tc, size) \
  texelFetch(map, ivec2(min((tc) * (size), (size) - 1.0)), 0).RF_DEPTH_CHANNEL
#define rf_float_of(x) float(x)

// Depth-peeled layers and the materials (rf_kernel_peel.h): GLSL passes no array of samplers
// or uniforms, so the kernel's handles are plain ints and the stage that defines RF_PEEL_LAYERS
// provides the lookups (shaders/rfMethodPEEL.glsl); the material table's handle is the
// colour channel whose indices are read (dispersion).
// The SH method's coefficient table: the stage that defines RF_SH_TABLE defines
// rf_sh_coefficient(table, i) too; the handle is the function (0..3) read.
#ifdef RF_SH_TABLE
#define rf_sh_table int
#endif
#ifdef RF_PEEL_LAYERS
#define rf_layer_stack int
#define rf_material_table int
vec4 rfPeelLayerTexel(ivec2 texel, int layer);
int rfPeelLayerSide(ivec2 texel, float depth);
float rfPeelLayerDepth(ivec2 texel, int layer);
float rfPeelMaterialIOR(int material, int channel);
bool rfPeelMaterialSheet(int material);
#define rf_layer_texel(layers, tc, size, i) \
  rfPeelLayerTexel(ivec2(min((tc) * (size), (size) - 1.0)), i)
#define rf_layer_depth(layers, tc, size, i) \
  rfPeelLayerDepth(ivec2(min((tc) * (size), (size) - 1.0)), i)
#define rf_layer_side(layers, count, tc, size, depth) \
  rfPeelLayerSide(ivec2(min((tc) * (size), (size) - 1.0)), depth)
#define rf_material_ior(materials, m) rfPeelMaterialIOR(m, materials)
#define rf_material_is_sheet(materials, m) rfPeelMaterialSheet(m)
#endif
