#pragma once
// PRT_CHECK: a broken internal invariant (a bug, never bad user input) aborts with a message.
// Bad user input is reported with prt::InputError instead (core/input_error.h).

#include <cstdio>
#include <cstdlib>

#define PRT_CHECK(cond)                                                                 \
  do {                                                                                  \
    if (!(cond)) {                                                                      \
      std::fprintf(stderr, "%s:%d: internal error: check failed: %s\n", __FILE__, __LINE__, \
                   #cond);                                                              \
      std::abort();                                                                     \
    }                                                                                   \
  } while (0)
