/* rf_jobs.h: running a few jobs at once on threads (the reference tracer's rows, the SH
 * precomputation's vertices). Private to the reference library. */
#ifndef RF_JOBS_H
#define RF_JOBS_H

#include <stddef.h>

/* Runs run(job) for each of the `count` jobs (elements of `size` bytes from `jobs`): job 0 on
 * the calling thread, the others on threads of their own; a job whose thread cannot be started
 * runs on the calling thread after job 0. Returns when all have finished; 0 when the thread
 * handles could not be allocated (nothing ran), 1 otherwise. */
int rf_run_jobs(void* jobs, size_t size, int count, void* (*run)(void*));

#endif /* RF_JOBS_H */
