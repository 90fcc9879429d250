/* real_format.h — doubles to the shortest JSON number text that reads back
 * as the same double (Grisu2), in the notation jansson uses. */
#ifndef API_REAL_FORMAT_H
#define API_REAL_FORMAT_H

#include <stddef.h>

/* Enough for every text api_real_format() writes (at most 25 bytes with the
 * NUL: "-1.2345678901234567e-308"). */
#define API_REAL_FORMAT_SIZE 32

/* Write finite x into buf as a NUL-terminated JSON number; return its length.
 *
 * Digits: Grisu2 (Loitsch 2010, "Printing floating-point numbers quickly and
 * accurately with integers", §5), at most 17 significant digits, which strtod
 * always reads back as x bit for bit; the shortest such digits in nearly all
 * cases (tests/api/test_json_write.c measures how often), correctly rounded
 * is not promised when several shortest texts exist.
 * Notation: that of jansson 2.14's json_dumps with JSON_REAL_PRECISION(17)
 * (printf %.17g, then src/strconv.c's touch-ups): scientific when the decimal
 * exponent X of the first digit is < -4 or >= 17, else fixed; no trailing
 * zeros; ".0" appended when the text would read as an integer ("1.0",
 * "-0.0", "100.0"); exponent without '+' or leading zeros ("1e21", "1e-7",
 * "2.5e-300"). Independent of the locale; no allocation; thread-safe.
 * Non-finite x (JSON has none; json_real() refuses them) writes "null". */
size_t api_real_format(double x, char buf[API_REAL_FORMAT_SIZE]);

#endif
