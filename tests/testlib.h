/* testlib.h — the few assertions mechd's C tests need, header-only.
 *
 * Each CHECK prints file:line and what failed, and counts; TEST_MAIN_END
 * prints "N passed, M failed" and returns nonzero on any failure, which CTest
 * reads as the test's result. Every test binary turns GSL's abort handler off.
 */
#ifndef MECHD_TESTLIB_H
#define MECHD_TESTLIB_H

#include <math.h>
#include <stdio.h>

static int tl_passed, tl_failed;

#define CHECK(cond)                                                            \
    do {                                                                       \
        if (cond) tl_passed++;                                                 \
        else { tl_failed++; fprintf(stderr, "%s:%d: CHECK failed: %s\n",       \
                                    __FILE__, __LINE__, #cond); }              \
    } while (0)

/* |got - want| <= atol + rtol * |want| */
#define CHECK_CLOSE(got, want, rtol, atol)                                     \
    do {                                                                       \
        double tl_g = (got), tl_w = (want);                                    \
        double tl_tol = (atol) + (rtol) * fabs(tl_w);                          \
        if (isfinite(tl_g) && fabs(tl_g - tl_w) <= tl_tol) tl_passed++;        \
        else { tl_failed++;                                                    \
            fprintf(stderr, "%s:%d: %s = %.17g, want %.17g (err %.3g, tol %.3g)\n", \
                    __FILE__, __LINE__, #got, tl_g, tl_w, fabs(tl_g - tl_w), tl_tol); } \
    } while (0)

#define CHECK_EQ_INT(got, want)                                                \
    do {                                                                       \
        long tl_g = (long)(got), tl_w = (long)(want);                          \
        if (tl_g == tl_w) tl_passed++;                                         \
        else { tl_failed++; fprintf(stderr, "%s:%d: %s = %ld, want %ld\n",     \
                                    __FILE__, __LINE__, #got, tl_g, tl_w); }   \
    } while (0)

#define TEST_MAIN_END()                                                        \
    do {                                                                       \
        printf("%d passed, %d failed\n", tl_passed, tl_failed);                \
        return tl_failed ? 1 : 0;                                              \
    } while (0)

#endif
