/* check.h - the self-checks of the example programs: CHECK_EQ counts a failure and prints it. */
#ifndef EXAMPLE_CHECK_H
#define EXAMPLE_CHECK_H

#include <stdio.h>

static int failures;

#define CHECK_EQ(what, got, want)                                                               \
    do {                                                                                        \
        long long g_ = (long long)(got), w_ = (long long)(want);                                \
        if (g_ != w_) {                                                                         \
            printf("FAIL %s: got 0x%llX, want 0x%llX\n", what, g_, w_);                         \
            failures++;                                                                         \
        }                                                                                       \
    } while (0)

#endif
