/* real_parse.h — a decimal w 10^q to the nearest double without strtod, for
 * the JSON number reader (api/json/json_read.c). */
#ifndef API_REAL_PARSE_H
#define API_REAL_PARSE_H

#include <stdint.h>

/* The double nearest w 10^q (w the decimal digits as an integer, w > 0 and
 * exact, i.e. no nonzero digit was dropped from it; ties to even: the value
 * glibc's correctly rounded strtod() gives for the same decimal), negated
 * when negative. Returns 1 with *out set, or 0 when this fast method cannot
 * decide (a result that is subnormal, zero or beyond the largest double, q
 * outside -342..308, or a product too close to a rounding boundary - rare
 * for any other input): the caller then asks strtod(). Thread-safe; no
 * allocation; no floating-point arithmetic (the bits are assembled). */
int api_real_from_decimal(uint64_t w, int q, int negative, double *out);

#endif
