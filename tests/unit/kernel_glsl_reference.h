/* kernel_glsl_reference.h: the C side of test_kernel_glsl (TestKernelGLSL.cxx): the cases of
 * rf_kernel_cases.h evaluated by the C kernel on the same inputs as the shader. */
#ifndef KERNEL_GLSL_REFERENCE_H
#define KERNEL_GLSL_REFERENCE_H

#ifdef __cplusplus
extern "C" {
#endif

/* The scene both sides share, every number already rounded to float (what the GPU receives). */
typedef struct rft_scene
{
  int width;
  int height;
  double projection[16]; /* row-major */
  double focal[2];       /* projection[0], projection[5] */
  double depth_range[2]; /* min and max of the non-empty depths */
  float* depth;          /* width x height back depths, row by row from the bottom */
} rft_scene;

/* Fills the scene: a perspective camera and the glass sphere's back depths. `depth` must hold
 * width x height floats. Returns the number of non-empty texels. */
int rft_make_scene(int width, int height, float* depth, rft_scene* scene);

/* Cases whose fourth value flags the branch under test (TIR; a search that moved): the two
 * refractions, and the searches from RFT_TEST_SEARCH_FIRST to RFT_TEST_SEARCH_LAST. */
#define RFT_TEST_REFRACT_REFLECT 0
#define RFT_TEST_REFRACT_CLAMP 1
#define RFT_TEST_SEARCH_FIRST 10
#define RFT_TEST_SEARCH_LAST 13

int rft_case_count(void);
const char* rft_case_name(int test_case);

/* The case at pixel (i, j) in C: out[4]. */
void rft_evaluate_pixel(const rft_scene* scene, int test_case, int i, int j, double out[4]);

/* 1 when the pixel's result lies within rounding of a discontinuity of the formula (the
 * critical angle under the reflect policy, a ground tile's edge, the octahedral seam, a
 * search decision that a depth or texture coordinate change of 1e-5 flips), where float and
 * double may rightly disagree. */
int rft_is_ambiguous(const rft_scene* scene, int test_case, int i, int j);

/* Relative tolerance of the case: |gpu - c| <= tolerance (1 + |c|). */
double rft_tolerance(int test_case);

#ifdef __cplusplus
}
#endif

#endif
