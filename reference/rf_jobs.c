/* rf_jobs.c: see rf_jobs.h. */
#include "rf_jobs.h"

#include <pthread.h>
#include <stdlib.h>

int rf_run_jobs(void* jobs, size_t size, int count, void* (*run)(void*))
{
  char* job = (char*)jobs;
  pthread_t* ids = (pthread_t*)calloc((size_t)(count > 0 ? count : 1), sizeof(pthread_t));
  int started = 0;
  int k;
  if (ids == NULL)
  {
    return 0;
  }
  for (k = 1; k < count; ++k)
  {
    if (pthread_create(&ids[k], NULL, run, job + (size_t)k * size) != 0)
    {
      break;
    }
    started = k;
  }
  if (count > 0)
  {
    run(job);
  }
  for (k = started + 1; k < count; ++k)
  {
    run(job + (size_t)k * size);
  }
  for (k = 1; k <= started; ++k)
  {
    pthread_join(ids[k], NULL);
  }
  free(ids);
  return 1;
}
