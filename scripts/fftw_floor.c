/* The FFT floor of a run: CPU inside FFTW against the process's whole CPU time (docs/performance.md,
 * "One mesh period against its FFT floor"). An LD_PRELOAD wrapper of fftw_execute that counts the
 * calls (the half-space solver's convolution is 4 calls, a "pair": rows and columns forward, then
 * back) and adds their wall time (CLOCK_MONOTONIC, read through the vDSO: a thread-CPU clock is a
 * system call and would cost more than a small transform; run on an idle core) and prints both at exit:
 *
 *   gcc -O2 -shared -fPIC -o /tmp/fftw_floor.so scripts/fftw_floor.c -ldl
 *   LD_PRELOAD=/tmp/fftw_floor.so build/camopt run studies/examples/cycloid_ltca_nnm_none.json --quiet --out /tmp/x
 *   -> fftw_floor: 46164 executes, 0.1447 s inside FFTW, process CPU 0.3452 s
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdio.h>
#include <time.h>

typedef void* fftw_plan;
static long calls;
static double seconds;
static void (*real_execute)(const fftw_plan);

void fftw_execute(const fftw_plan p) {
  if (!real_execute) real_execute = (void (*)(const fftw_plan))dlsym(RTLD_NEXT, "fftw_execute");
  struct timespec a, b;
  clock_gettime(CLOCK_MONOTONIC, &a);
  real_execute(p);
  clock_gettime(CLOCK_MONOTONIC, &b);
  seconds += (double)(b.tv_sec - a.tv_sec) + 1e-9 * (double)(b.tv_nsec - a.tv_nsec);
  ++calls;
}

__attribute__((destructor)) static void report(void) {
  struct timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  fprintf(stderr, "fftw_floor: %ld executes, %.4f s inside FFTW, process CPU %.4f s\n", calls, seconds,
          (double)t.tv_sec + 1e-9 * (double)t.tv_nsec);
}
