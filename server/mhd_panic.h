/* mhd_panic.h — libmicrohttpd's panic handler: survive the one panic of
 * libmicrohttpd 0.9.75 that is a harmless race, abort on every other. */
#ifndef SRV_MHD_PANIC_H
#define SRV_MHD_PANIC_H

/* Install srv_mhd_panic as libmicrohttpd's panic handler (MHD_set_panic_func;
 * process-wide: call once in main before any daemon starts). */
void srv_mhd_panic_install(void);

/* 1 if a libmicrohttpd panic with this reason and errno is the known harmless
 * race (see mhd_panic.c), 0 otherwise. reason may be NULL (then 0). Pure. */
int srv_mhd_panic_is_benign(const char *reason, int err);

/* The handler: logs the panic; returns for a benign one (libmicrohttpd then
 * carries on as if the call had succeeded), aborts otherwise. */
void srv_mhd_panic(void *cls, const char *file, unsigned int line, const char *reason);

#endif
