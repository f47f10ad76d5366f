// LAPACK's error handler, XERBLA, for the ogive program, which links LAPACK's static archive
// (cli/CMakeLists.txt). LAPACK's own XERBLA is the only routine of those linked (Clp's dense LU: DGETRF,
// DGETRS and what they call) that uses Fortran I/O: it alone would bring the whole Fortran runtime into
// the program, with a constructor that sets up its I/O units at every start. LAPACK documents XERBLA as
// the routine an installer replaces; this one does what the reference routine does: the same line on
// standard output, then STOP (exit status 0). It is reached only when LAPACK is called with an invalid
// argument.
#include <cstddef>
#include <cstdio>
#include <cstdlib>

// Fortran's calling convention: every argument by reference, the string's length appended by value.
extern "C" void xerbla_(const char* name, const int* info, std::size_t name_length) {
  while (name_length > 0 && name[name_length - 1] == ' ') --name_length;
  char number[3] = "**";  // the format I2: two columns, stars when the number does not fit
  if (*info >= -9 && *info <= 99) std::snprintf(number, sizeof number, "%2d", *info);
  std::printf(" ** On entry to %.*s parameter number %s had an illegal value\n", static_cast<int>(name_length),
              name, number);
  std::exit(0);
}
