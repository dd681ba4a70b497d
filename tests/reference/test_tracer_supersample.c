/* The supersampled reference (samples_per_side) against closed forms: a glass block whose
 * edge splits one pixel column at a known fraction, over a constant environment, so that
 * every glass sub-sample reads the environment's colour exactly (F c + (1 - F) c in the
 * two-interface mode, energy conservation in the full mode) and every pixel's colour is
 * coverage * c + (1 - coverage) * background with the coverage counted here from the
 * sub-sample grid. Also the progress callback and the rejected options. */
#include "rf_reference_test.h"

#include "rf_test.h"

#include <stdio.h>

#define WIDTH 24
#define HEIGHT 16
#define SCALE 1.0
#define EDGE_COLUMN 9
#define EDGE_FRACTION 0.33 /* of EDGE_COLUMN's width lies on the glass */

static const double environment_colour[3] = { 0.2, 0.45, 0.7 };
static const double background_colour[3] = { 1.0, 0.0, 0.25 };

static void constant_environment(const double direction[3], double rgb[3], void* user)
{
  int c;
  (void)direction;
  (void)user;
  for (c = 0; c < 3; ++c)
  {
    rgb[c] = environment_colour[c];
  }
}

typedef struct progress_record
{
  int calls;
  int monotone;
  double last;
} progress_record;

static void record_progress(double fraction, void* user)
{
  progress_record* record = (progress_record*)user;
  record->monotone = record->monotone && fraction >= record->last && fraction <= 1.0;
  record->last = fraction;
  ++record->calls;
}

/* Share of an n x n grid of sub-samples, at (a + 0.5) / n across the column, that lie left
 * of the edge. */
static double expected_coverage(int column, int n)
{
  int a;
  int inside = 0;
  if (column < EDGE_COLUMN)
  {
    return 1.0;
  }
  if (column > EDGE_COLUMN)
  {
    return 0.0;
  }
  for (a = 0; a < n; ++a)
  {
    inside += (a + 0.5) / n < EDGE_FRACTION ? 1 : 0;
  }
  return (double)inside / n;
}

/* Parallel camera at the origin looking down -z, half height SCALE. */
static rf_camera make_camera(void)
{
  return rft_parallel_camera(0.0, SCALE, WIDTH, HEIGHT, 0.5, 20.0);
}

static void run(rf_trace_mode mode, int n)
{
  const double aspect = (double)WIDTH / HEIGHT;
  /* World x of the edge: the NDC of EDGE_COLUMN + EDGE_FRACTION times the half width. */
  const double edge = ((EDGE_COLUMN + EDGE_FRACTION) / WIDTH * 2.0 - 1.0) * SCALE * aspect;
  const double centre[3] = { 0.5 * (edge - 50.0), 0.0, -5.0 };
  const double half[3] = { 0.5 * (edge + 50.0), 50.0, 1.0 };
  rft_box_scene scene;
  rf_trace_options* const options = &scene.options;
  const rf_trace_image* const image = &scene.image;
  progress_record progress = { 0, 1, 0.0 };
  double worst_colour = 0.0;
  double worst_coverage = 0.0;
  int i;
  int j;
  int c;
  rft_box_scene_init(&scene, centre, half, NULL, 1.5, make_camera());
  CHECK(options->samples_per_side == 1 && options->progress == NULL);
  options->mode = mode;
  options->environment = constant_environment;
  options->samples_per_side = n;
  for (c = 0; c < 3; ++c)
  {
    options->background[c] = background_colour[c];
  }
  options->progress = record_progress;
  options->progress_user = &progress;
  CHECK(rft_box_scene_trace(&scene) == RF_OK);
  for (j = 0; j < HEIGHT; ++j)
  {
    for (i = 0; i < WIDTH; ++i)
    {
      const size_t index = (size_t)j * WIDTH + (size_t)i;
      const double coverage = expected_coverage(i, n);
      /* With one sample, a pixel without glass is 0 whatever the background. */
      const int centre_hit = (i + 0.5) / WIDTH < (EDGE_COLUMN + EDGE_FRACTION) / WIDTH;
      worst_coverage = fmax(worst_coverage, fabs(image->coverage[index] - coverage));
      CHECK(image->hit[index] == centre_hit);
      for (c = 0; c < 3; ++c)
      {
        const double expected = n == 1
          ? (centre_hit ? environment_colour[c] : 0.0)
          : coverage * environment_colour[c] + (1.0 - coverage) * background_colour[c];
        worst_colour = fmax(worst_colour, fabs(image->colour[3 * index + c] - expected));
      }
    }
  }
  CHECK_NEAR(worst_coverage, 0.0, 1e-7);
  CHECK_NEAR(worst_colour, 0.0, 1e-6);
  /* The calling thread reports after each of its rows (2 threads: every other row). */
  CHECK(progress.calls >= HEIGHT / 2);
  CHECK(progress.monotone);
  CHECK(progress.last >= 1.0 - 2.0 / HEIGHT);
  printf("mode %d, %dx%d samples: edge pixel coverage %.3f, worst colour error %.1e\n", (int)mode,
    n, n, image->coverage[EDGE_COLUMN], worst_colour);
  rf_trace_image_free(&scene.image);
}

static void test_rejected(void)
{
  const double centre[3] = { 0.0, 0.0, -5.0 };
  const double half[3] = { 1.0, 1.0, 1.0 };
  rft_box_scene scene;
  rft_box_scene_init(&scene, centre, half, NULL, 1.5, make_camera());
  scene.options.samples_per_side = 0;
  CHECK(rft_box_scene_trace(&scene) == RF_REF_ERR_BAD_OPTION);
  scene.options.samples_per_side = RF_TRACE_MAX_SAMPLES_PER_SIDE + 1;
  CHECK(rft_box_scene_trace(&scene) == RF_REF_ERR_BAD_OPTION);
  scene.options.samples_per_side = RF_TRACE_MAX_SAMPLES_PER_SIDE;
  scene.options.background[1] = NAN;
  CHECK(rft_box_scene_trace(&scene) == RF_ERR_NOT_FINITE);
  rf_trace_image_free(&scene.image);
}

int main(void)
{
  run(RF_TRACE_TWO_INTERFACE, 1);
  run(RF_TRACE_TWO_INTERFACE, 4);
  run(RF_TRACE_TWO_INTERFACE, 5);
  run(RF_TRACE_FULL, 4);
  test_rejected();
  return RF_TEST_SUMMARY();
}
