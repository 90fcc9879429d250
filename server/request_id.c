/* request_id.c — the X-Request-Id of each request: the client's own when it
 * is safe to echo, else 128 bits from a per-thread generator seeded by the
 * kernel (part of the HTTP front end, see http.c; declared in
 * http_internal.h). */
#ifdef __linux__
#define _GNU_SOURCE
#endif
#include "http_internal.h"

#include <stdatomic.h>
#include <string.h>
#include <sys/random.h>
#include <time.h>
#include <unistd.h>

/* May a client-given X-Request-Id be kept? 1..SRV_REQUEST_ID_MAX characters of
 * [A-Za-z0-9._:+/=-]: enough for UUIDs, hex, base64 and the ids proxies make,
 * nothing that needs escaping in a header, a log line or a JSON string. */
static int request_id_ok(const char *s)
{
    size_t n = 0;
    if (!s) return 0;
    for (; s[n]; n++) {
        char c = s[n];
        if (n >= SRV_REQUEST_ID_MAX ||
            !((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
              c == '.' || c == '_' || c == ':' || c == '+' || c == '/' || c == '=' || c == '-'))
            return 0;
    }
    return n > 0;
}

/* 64 bits of splitmix64 from *x (advances it). */
static unsigned long long splitmix64(unsigned long long *x)
{
    unsigned long long z = (*x += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

static unsigned long long rotl64(unsigned long long v, int k)
{
    return (v << k) | (v >> (64 - k));
}

/* This thread's xoshiro256** state for request ids, seeded on first use. */
static _Thread_local unsigned long long tl_id_state[4];
static _Thread_local int tl_id_seeded;

/* Seed tl_id_state with 256 bits from getrandom(2); should the kernel refuse
 * them, from the clock, the process id and a process-wide counter through
 * splitmix64 (unique within the process, very likely across). */
static void id_seed(struct srv_http *h)
{
    ssize_t got = getrandom(tl_id_state, sizeof tl_id_state, GRND_NONBLOCK);
    if (got != (ssize_t)sizeof tl_id_state) {
        struct timespec ts;
        clock_gettime(CLOCK_REALTIME, &ts);
        unsigned long long x = (unsigned long long)ts.tv_sec * 1000000000ULL +
                               (unsigned long long)ts.tv_nsec +
                               ((unsigned long long)getpid() << 40) +
                               atomic_fetch_add(&h->next_id, 1) * 0x2545f4914f6cdd1dULL;
        for (int i = 0; i < 4; i++)
            tl_id_state[i] = splitmix64(&x);
    }
    if (!(tl_id_state[0] | tl_id_state[1] | tl_id_state[2] | tl_id_state[3])) tl_id_state[0] = 1;
    tl_id_seeded = 1;
}

/* The next 64 bits of this thread's xoshiro256** generator. */
static unsigned long long id_next(void)
{
    unsigned long long *s = tl_id_state;
    unsigned long long out = rotl64(s[1] * 5, 7) * 9, t = s[1] << 17;
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = rotl64(s[3], 45);
    return out;
}

/* A request id into out (SRV_REQUEST_ID_MAX + 1 bytes): `given` (the incoming
 * X-Request-Id) when request_id_ok, else 32 lower-case hex digits of 128 bits
 * from this thread's xoshiro256** generator, seeded with 256 bits from
 * getrandom(2) on the thread's first request, so ids from any number of
 * threads and replicas do not collide (probability ~2^-65 for 2^32 requests)
 * without coordination, and a request costs no system call for its id. */
void request_id(struct srv_http *h, const char *given, char *out)
{
    if (request_id_ok(given)) {
        strcpy(out, given);
        return;
    }
    if (!tl_id_seeded) id_seed(h);
    unsigned char b[16];
    for (int half = 0; half < 2; half++) {
        unsigned long long z = id_next();
        for (int i = 0; i < 8; i++)
            b[half * 8 + i] = (unsigned char)(z >> (8 * i));
    }
    static const char hex[] = "0123456789abcdef";
    for (int i = 0; i < 16; i++) {
        out[2 * i] = hex[b[i] >> 4];
        out[2 * i + 1] = hex[b[i] & 15];
    }
    out[32] = '\0';
}
