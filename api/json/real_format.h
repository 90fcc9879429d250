/* real_format.h — doubles to JSON number text: the shortest decimal that
 * reads back as the same double, in a fixed layout. */
#ifndef API_REAL_FORMAT_H
#define API_REAL_FORMAT_H

#include <stddef.h>

/* Enough for every text api_real_format() writes (at most 25 bytes with the
 * NUL: "-1.2345678901234567e-308"). */
#define API_REAL_FORMAT_SIZE 32

/* Write finite x into buf as a NUL-terminated JSON number; return its length.
 *
 * Digits: the fewest significant decimal digits (1 to 17) of any decimal
 * that strtod() (any correctly rounding reader: JavaScript, Python, Java)
 * reads back as x bit for bit; among equally short ones the one nearest x,
 * ties to an even last digit - the digits of JavaScript's Number.toString
 * and Python's repr. Layout, as printf's %.17g with jansson's touch-ups:
 * with X the decimal exponent of the first digit, scientific
 * ("d.ddde-7", exponent without '+' or leading zeros: "1e21", "2.5e-300")
 * when X < -4 or X >= 17, else fixed ("0.00012", "299792458.0"), and ".0"
 * appended when the text would read as an integer ("1.0", "-0.0",
 * "10000000000000000.0"). The same x always gives the same bytes.
 * Independent of the locale; no allocation; thread-safe. Non-finite x (JSON
 * has none; json_real() refuses them) writes "null". */
size_t api_real_format(double x, char buf[API_REAL_FORMAT_SIZE]);

#endif
