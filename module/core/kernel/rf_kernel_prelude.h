/* rf_kernel_prelude.h: the C side of the kernel dialect. The kernel headers beside this file
 * (rf_kernel_*.h) are written once in a subset of C99 that is also GLSL 1.50 once the macros
 * below are replaced by shaders/rfKernelPrelude.glsl (Blender Cycles' kernel is the model: one
 * source for CPU and GPU behind a thin layer). Here the scalar is a double, vectors are small
 * structs with .x/.y/.z/.w members, operations are functions, and a depth map is a callback.
 *
 * Rules for kernel code (what both compilers accept):
 *  - types rf_float, rf_float2/3/4, rf_mat4, rf_bool, int, and RF_STRUCT_BEGIN(name) ... };
 *  - vector arithmetic only through rf_add3, rf_scale3, ... (C has no operators on structs);
 *    components through .x .y .z .w only (no swizzles, no indexing);
 *  - floating literals with a decimal point and no suffix (1.0, 1e-6), never 1 for a float;
 *  - conditions are comparisons or rf_bool values, never an int or a float;
 *  - out parameters as RF_OUT(type) name, written and read as RF_DEREF(name), passed as
 *    RF_ADDR(local); no pointers otherwise, no arrays, no recursion, no const locals computed
 *    at run time (GLSL 1.50 wants constant expressions there);
 *  - kernel functions are RF_KERNEL and named rfk_* (or rf_oct_*): the public C core keeps the
 *    plain names (rf_refract, ...) for its validating wrappers;
 *  - #include lines only inside #ifndef RF_GLSL (the embedding drops them). */
#ifndef RF_KERNEL_PRELUDE_H
#define RF_KERNEL_PRELUDE_H

#include "../rf_vec3.h"

#include <math.h>

#define RF_KERNEL static inline
#define RF_OUT(type) type*
#define RF_INOUT(type) type*
#define RF_DEREF(name) (*(name))
#define RF_ADDR(name) (&(name))
#define RF_TRUE 1
#define RF_FALSE 0
#define RF_STRUCT_BEGIN(name)                                                                      \
  typedef struct name name;                                                                        \
  struct name                                                                                      \
  {

typedef double rf_float;
typedef int rf_bool;
typedef rf_vec3 rf_float3;
typedef struct rf_float2
{
  double x, y;
} rf_float2;
typedef struct rf_float4
{
  double x, y, z, w;
} rf_float4;
/* A 4x4 matrix applied to column vectors, ROW-MAJOR (m[row * 4 + col]); in GLSL a mat4
 * uniform as VTK uploads its key matrices. */
typedef struct rf_mat4
{
  double m[16];
} rf_mat4;

/* A depth map: sample(context, tc) returns the stored POSITIVE depth at texture coordinates tc
 * in [0, 1]^2 (0 for an empty texel), as the GLSL side's texelFetch of the nearest texel
 * (rf_texel_index gives the same texel). */
typedef struct rf_depth_map
{
  double (*sample)(void* context, const double tc[2]);
  void* context;
} rf_depth_map;

static inline rf_float2 rf_make2(double x, double y)
{
  rf_float2 v;
  v.x = x;
  v.y = y;
  return v;
}
#define rf_make3 rf_vec3_make
static inline rf_float4 rf_make4(double x, double y, double z, double w)
{
  rf_float4 v;
  v.x = x;
  v.y = y;
  v.z = z;
  v.w = w;
  return v;
}

static inline rf_float2 rf_add2(rf_float2 a, rf_float2 b) { return rf_make2(a.x + b.x, a.y + b.y); }
static inline rf_float2 rf_sub2(rf_float2 a, rf_float2 b) { return rf_make2(a.x - b.x, a.y - b.y); }
static inline rf_float2 rf_scale2(rf_float2 v, double s) { return rf_make2(v.x * s, v.y * s); }
static inline rf_float2 rf_mul2(rf_float2 a, rf_float2 b) { return rf_make2(a.x * b.x, a.y * b.y); }
static inline double rf_dot2(rf_float2 a, rf_float2 b) { return a.x * b.x + a.y * b.y; }
static inline double rf_length2(rf_float2 v) { return sqrt(rf_dot2(v, v)); }

#define rf_add3 rf_vec3_add
#define rf_sub3 rf_vec3_sub
#define rf_scale3 rf_vec3_scale
#define rf_dot3 rf_vec3_dot
#define rf_cross3 rf_vec3_cross
#define rf_length3 rf_vec3_length
/* Unit vector; zero for a zero vector (GLSL's normalize gives NaN there: kernel code only
 * normalizes vectors it knows to be non-zero). */
#define rf_normalize3 rf_vec3_normalize
static inline rf_float3 rf_neg3(rf_float3 v) { return rf_vec3_make(-v.x, -v.y, -v.z); }
static inline rf_float3 rf_div3(rf_float3 v, double s)
{
  return rf_vec3_make(v.x / s, v.y / s, v.z / s);
}
/* GLSL mix(a, b, t) = a + (b - a) t, per component. */
static inline rf_float3 rf_mix3(rf_float3 a, rf_float3 b, double t)
{
  return rf_vec3_make(a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t);
}
/* GLSL reflect(I, N) = I - 2 dot(N, I) N. */
static inline rf_float3 rf_reflect3(rf_float3 incident, rf_float3 normal)
{
  return rf_vec3_sub(incident, rf_vec3_scale(normal, 2.0 * rf_vec3_dot(normal, incident)));
}

static inline rf_float4 rf_mul_mat4(rf_mat4 m, rf_float4 v)
{
  return rf_make4(m.m[0] * v.x + m.m[1] * v.y + m.m[2] * v.z + m.m[3] * v.w,
    m.m[4] * v.x + m.m[5] * v.y + m.m[6] * v.z + m.m[7] * v.w,
    m.m[8] * v.x + m.m[9] * v.y + m.m[10] * v.z + m.m[11] * v.w,
    m.m[12] * v.x + m.m[13] * v.y + m.m[14] * v.z + m.m[15] * v.w);
}

#define rf_abs fabs
#define rf_sqrt sqrt
#define rf_floor floor
#define rf_ceil ceil
#define rf_log2 log2
#define rf_pow pow
#define rf_acos acos
#define rf_sin sin
#define rf_cos cos
#define rf_atan2 atan2
#define rf_isinf isinf
static inline double rf_min(double a, double b) { return a < b ? a : b; }
static inline double rf_max(double a, double b) { return a > b ? a : b; }
static inline double rf_clamp(double x, double lo, double hi) { return rf_min(rf_max(x, lo), hi); }
static inline double rf_fract(double x) { return x - floor(x); }
static inline double rf_mix(double a, double b, double t) { return a + (b - a) * t; }
static inline double rf_smoothstep(double e0, double e1, double x)
{
  const double t = rf_clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}
/* +1 or -1, never 0 (GLSL sign() gives 0 at 0). */
static inline double rf_sign_not_zero(double x) { return x < 0.0 ? -1.0 : 1.0; }
static inline int rf_imin(int a, int b) { return a < b ? a : b; }
static inline int rf_int_of(double x) { return (int)x; }

/* The texel a GLSL texelFetch reads for tc: ivec2(min(tc * size, size - 1)). For C samplers
 * that stand for a texture. */
static inline void rf_texel_index(const double tc[2], const double size[2], int texel[2])
{
  texel[0] = (int)rf_min(tc[0] * size[0], size[0] - 1.0);
  texel[1] = (int)rf_min(tc[1] * size[1], size[1] - 1.0);
}

/* The stored depth at tc (already inside [0, 1]^2); `size` is the map's size in texels, used by
 * the GLSL side's texelFetch and by C samplers through their context. */
static inline double rf_sample_depth(rf_depth_map map, rf_float2 tc, rf_float2 size)
{
  double at[2];
  (void)size;
  at[0] = tc.x;
  at[1] = tc.y;
  return map.sample(map.context, at);
}

static inline double rf_float_of(int x) { return (double)x; }

/* Depth-peeled layers (rf_kernel_peel.h): texel(context, tc, layer) returns layer `layer` at
 * texture coordinates tc in [0, 1]^2 as the GLSL side's texelFetch of the nearest texel. */
typedef struct rf_layer_stack
{
  rf_float4 (*texel)(void* context, const double tc[2], int layer);
  void* context;
} rf_layer_stack;

static inline rf_float4 rf_layer_texel(rf_layer_stack layers, rf_float2 tc, rf_float2 size, int i)
{
  double at[2];
  (void)size;
  at[0] = tc.x;
  at[1] = tc.y;
  return layers.texel(layers.context, at, i);
}

/* The depth (z) of layer i at tc. */
static inline double rf_layer_depth(rf_layer_stack layers, rf_float2 tc, rf_float2 size, int i)
{
  return rf_layer_texel(layers, tc, size, i).z;
}

/* How many of the first `count` layers at tc hold a surface nearer than depth. */
static inline int rf_layer_side(rf_layer_stack layers, int count, rf_float2 tc, rf_float2 size,
  double depth)
{
  int side = 0;
  int i;
  for (i = 0; i < count; ++i)
  {
    const double stored = rf_layer_texel(layers, tc, size, i).z;
    side += stored > 0.0 && stored < depth ? 1 : 0;
  }
  return side;
}

/* Spherical-harmonic coefficients (rf_kernel_sh.h), read by index. */
typedef struct rf_sh_table
{
  const double* values;
} rf_sh_table;

static inline double rf_sh_coefficient(rf_sh_table table, int i)
{
  return table.values[i];
}

/* The glass materials by index: their index of refraction, and whether each is a thin sheet. */
typedef struct rf_material_table
{
  const double* ior;
  const int* sheet; /* may be NULL: no sheets */
  int count;
} rf_material_table;

static inline double rf_material_ior(rf_material_table materials, int m)
{
  return materials.ior[m < 0 ? 0 : (m < materials.count ? m : materials.count - 1)];
}

static inline rf_bool rf_material_is_sheet(rf_material_table materials, int m)
{
  return materials.sheet && m >= 0 && m < materials.count && materials.sheet[m] != 0;
}

#endif /* RF_KERNEL_PRELUDE_H */
