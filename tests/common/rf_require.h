// RF_REQUIRE(cond, printf-style message...): the check the C++ tests share. On failure it
// prints the place, the condition and the message, and returns EXIT_FAILURE from the caller.
#ifndef rf_require_h
#define rf_require_h

#include <cstdio>
#include <cstdlib>

#define RF_REQUIRE(cond, ...)                                                                     \
  do                                                                                               \
  {                                                                                                \
    if (!(cond))                                                                                   \
    {                                                                                              \
      std::fprintf(stderr, "FAILED %s:%d: %s: ", __FILE__, __LINE__, #cond);                       \
      std::fprintf(stderr, __VA_ARGS__);                                                           \
      std::fprintf(stderr, "\n");                                                                  \
      return EXIT_FAILURE;                                                                         \
    }                                                                                              \
  } while (0)

#endif
