/* rf_tracer_pixels.c: supersampling and the image loop (see rf_tracer_pixels.h). */
#include "rf_tracer_pixels.h"

#include "rf_jobs.h"
#include "rf_tracer_camera.h"

#include <stdlib.h>

static void rf_store_vec3(float* array, size_t index, rf_vec3 v)
{
  if (array != NULL)
  {
    array[3 * index + 0] = (float)v.x;
    array[3 * index + 1] = (float)v.y;
    array[3 * index + 2] = (float)v.z;
  }
}

static void rf_trace_pixel(const rf_tracer* tr, int i, int j)
{
  rf_trace_image* out = tr->out;
  const size_t index = (size_t)j * (size_t)out->width + (size_t)i;
  const int n = tr->options->samples_per_side;
  rf_pixel px;
  double colour[3];
  double coverage;
  int c;
  /* OpenGL's pixel centres (rasterization samples at the centre). */
  rf_trace_primary(
    tr, (i + 0.5) / out->width * 2.0 - 1.0, (j + 0.5) / out->height * 2.0 - 1.0, &px);
  for (c = 0; c < 3; ++c)
  {
    colour[c] = px.colour[c];
  }
  coverage = px.hit ? 1.0 : 0.0;
  if (n > 1)
  {
    int a;
    int b;
    int hits = 0;
    for (c = 0; c < 3; ++c)
    {
      colour[c] = 0.0;
    }
    for (b = 0; b < n; ++b)
    {
      for (a = 0; a < n; ++a)
      {
        rf_pixel sample;
        rf_trace_primary(tr, (i + (a + 0.5) / n) / out->width * 2.0 - 1.0,
          (j + (b + 0.5) / n) / out->height * 2.0 - 1.0, &sample);
        hits += sample.hit;
        for (c = 0; c < 3; ++c)
        {
          colour[c] += sample.hit || sample.opaque ? sample.colour[c] : tr->options->background[c];
        }
      }
    }
    for (c = 0; c < 3; ++c)
    {
      colour[c] /= (double)(n * n);
    }
    coverage = (double)hits / (double)(n * n);
  }
  if (out->colour != NULL)
  {
    out->colour[3 * index + 0] = (float)colour[0];
    out->colour[3 * index + 1] = (float)colour[1];
    out->colour[3 * index + 2] = (float)colour[2];
  }
  if (out->coverage != NULL)
  {
    out->coverage[index] = (float)coverage;
  }
  if (px.hit)
  {
    rf_store_vec3(out->p1, index, rf_mat4_point(tr->world_to_view, px.p1));
    rf_store_vec3(out->p2, index, rf_mat4_point(tr->world_to_view, px.p2));
    rf_store_vec3(out->t2, index, rf_mat4_direction(tr->world_to_view, px.t2));
  }
  else
  {
    const rf_vec3 zero = rf_vec3_make(0.0, 0.0, 0.0);
    rf_store_vec3(out->p1, index, zero);
    rf_store_vec3(out->p2, index, zero);
    rf_store_vec3(out->t2, index, zero);
  }
  if (out->thickness != NULL)
  {
    out->thickness[index] = (float)px.thickness;
  }
  if (out->bounces != NULL)
  {
    out->bounces[index] = px.bounces;
  }
  if (out->tir != NULL)
  {
    out->tir[index] = (unsigned char)(px.tir ? 1 : 0);
  }
  if (out->hit != NULL)
  {
    out->hit[index] = (unsigned char)(px.hit ? 1 : 0);
  }
  if (out->opaque != NULL)
  {
    out->opaque[index] = (unsigned char)(px.opaque ? 1 : 0);
  }
}

typedef struct rf_worker
{
  const rf_tracer* tracer;
  int first_row;
  int row_step;
  int report_progress; /* the worker on the calling thread */
} rf_worker;

/* Rows are interleaved over the workers so that each gets a similar share of the object. */
static void* rf_worker_run(void* arg)
{
  const rf_worker* w = (const rf_worker*)arg;
  const int width = w->tracer->out->width;
  const int height = w->tracer->out->height;
  int j;
  int i;
  for (j = w->first_row; j < height; j += w->row_step)
  {
    for (i = 0; i < width; ++i)
    {
      rf_trace_pixel(w->tracer, i, j);
    }
    /* Rows are interleaved, so the calling thread's share of rows stands for all of them. */
    if (w->report_progress && w->tracer->options->progress != NULL)
    {
      w->tracer->options->progress(
        (double)(j + 1) / (double)height, w->tracer->options->progress_user);
    }
  }
  return NULL;
}

rf_status rf_run_workers(const rf_tracer* tr, int threads)
{
  rf_worker* workers;
  int ran;
  int k;
  if (threads > tr->out->height)
  {
    threads = tr->out->height;
  }
  workers = (rf_worker*)calloc((size_t)threads, sizeof(rf_worker));
  if (workers == NULL)
  {
    return RF_REF_ERR_OUT_OF_MEMORY;
  }
  for (k = 0; k < threads; ++k)
  {
    workers[k].tracer = tr;
    workers[k].first_row = k;
    workers[k].row_step = threads;
    workers[k].report_progress = k == 0;
  }
  ran = rf_run_jobs(workers, sizeof(rf_worker), threads, rf_worker_run);
  free(workers);
  return ran ? RF_OK : RF_REF_ERR_OUT_OF_MEMORY;
}
