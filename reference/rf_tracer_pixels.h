/* rf_tracer_pixels.h: the image loop (private): every pixel, its centre or N x N sub-samples
 * averaged (samples_per_side), written to the image, rows interleaved over worker threads. */
#ifndef RF_TRACER_PIXELS_H
#define RF_TRACER_PIXELS_H

#include "rf_tracer_state.h"

/* Traces every pixel of tr->out on `threads` threads (at most one per row). */
rf_status rf_run_workers(const rf_tracer* tr, int threads);

#endif /* RF_TRACER_PIXELS_H */
