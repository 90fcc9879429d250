/* real_format.h — doubles to JSON number text exactly as jansson's
 * json_dumps(JSON_REAL_PRECISION(17)) writes them, without its cost. */
#ifndef API_REAL_FORMAT_H
#define API_REAL_FORMAT_H

#include <stddef.h>

/* Enough for every text api_real_format() writes (at most 25 bytes with the
 * NUL: "-1.2345678901234567e-308"). */
#define API_REAL_FORMAT_SIZE 32

/* Write finite x into buf as a NUL-terminated JSON number; return its length.
 *
 * The text is byte for byte what jansson 2.14's json_dumps writes with
 * JSON_REAL_PRECISION(17): printf's %.17g (17 significant digits, correctly
 * rounded, which strtod reads back as x bit for bit; scientific when the
 * decimal exponent X of the first digit is < -4 or >= 17, else fixed; no
 * trailing zeros), then src/strconv.c's touch-ups: ".0" appended when the
 * text would read as an integer ("1.0", "-0.0", "100.0"), exponent without
 * '+' or leading zeros ("1e21", "9.9999999999999995e-8"). The digits come
 * from a 64-bit scaled product, or from snprintf where that cannot decide
 * the rounding (see real_format.c). Independent of the locale; no
 * allocation; thread-safe. Non-finite x (JSON has none; json_real() refuses
 * them) writes "null". */
size_t api_real_format(double x, char buf[API_REAL_FORMAT_SIZE]);

#endif
