/* A minimal check macro for the C tests: prints the failed condition and
 * the library's last error, and counts failures. */
#ifndef ISOFORM_TEST_CHECK_H
#define ISOFORM_TEST_CHECK_H

#include <stdio.h>

#include "isoform.h"

static int check_failures = 0;

#define CHECK(cond)                                                                          \
  do {                                                                                       \
    if (!(cond)) {                                                                           \
      fprintf(stderr, "%s:%d: CHECK failed: %s (last error: %s)\n", __FILE__, __LINE__, #cond, \
              isoform_last_error());                                                        \
      ++check_failures;                                                                      \
    }                                                                                        \
  } while (0)

#endif
