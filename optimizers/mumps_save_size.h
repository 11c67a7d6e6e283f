// Whether this program skips MUMPS's size-of-a-save bookkeeping after each call
// (optimizers/mumps_save_size.cc says why and how).
#pragma once

namespace camopt::optimizers {

// True when the program's no-op definition is compiled in (MUMPS 5.3–5.x found at configure time)
// and is the one the dynamic linker binds, libdmumps's own calls included.
bool MumpsSaveSizeSkipped();

}  // namespace camopt::optimizers
