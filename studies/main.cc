// camopt: the command line (studies/cli.cc).
#include <malloc.h>

#include "studies/cli.h"

int main(int argc, char** argv) {
  // glibc's malloc gives the top of its heap back to the system whenever more than 128 kB lie free
  // there, and a sizing frees and re-allocates its per-evaluation blocks thousands of times: each
  // return was paid again in fresh zeroed pages (lcr_min_size_lubricated: 5 754 brk calls, 193 000
  // page faults, 1.5 s of its 7.6 s of CPU in the kernel). A run is one process, so the heap keeps up
  // to 64 MB free at its top, grows 16 MB at a time, and blocks up to 32 MB come from the heap
  // instead of their own mappings (docs/performance.md "System time"). No effect under ASan's
  // allocator; the Python module and the library leave the host's allocator alone.
  mallopt(M_TRIM_THRESHOLD, 64 << 20);
  mallopt(M_TOP_PAD, 16 << 20);
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  return camopt::studies::CliMain(argc, argv);
}
