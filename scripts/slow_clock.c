// Preloaded by render_instructions.sh: clock_gettime runs 1000 times slower than the wall
// clock. The renderer sizes its passes by elapsed time (at most 2 s a pass), and each pass
// sets up its samplers again, so under valgrind the count of passes, and with it 1% of
// the instructions, would follow the machine's load; with time slowed every render takes
// the passes of an unloaded one (1, 1, 2, 4, 8 ... samples).
#define _GNU_SOURCE
#include <dlfcn.h>
#include <time.h>

int clock_gettime(clockid_t id, struct timespec* ts) {
    static int (*real)(clockid_t, struct timespec*);
    static long long start[16];
    static int started[16];
    if (!real) real = (int (*)(clockid_t, struct timespec*))dlsym(RTLD_NEXT, "clock_gettime");
    const int r = real(id, ts);
    if (r != 0 || id < 0 || id >= 16) return r;
    long long ns = ts->tv_sec * 1000000000LL + ts->tv_nsec;
    if (!started[id]) {
        started[id] = 1;
        start[id] = ns;
    }
    ns = start[id] + (ns - start[id]) / 1000;
    ts->tv_sec = ns / 1000000000LL;
    ts->tv_nsec = ns % 1000000000LL;
    return r;
}
