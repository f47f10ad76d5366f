// fmt's compiled part (what Debian's libfmt.so holds, built as its src/format.cc builds it), compiled
// into the ogive program alone: Debian ships no libfmt.a, and libfmt.so would load the shared libstdc++
// that the program links statically (cli/CMakeLists.txt). The functions come from fmt's own
// format-inl.h, defined here out of line; the library and the tests keep linking libfmt.so.
#include <fmt/format-inl.h>

FMT_BEGIN_NAMESPACE
namespace detail {
// Declared `extern template` by fmt/format.h, so instantiated here as format.cc does.
template FMT_API auto thousands_sep_impl(locale_ref) -> thousands_sep_result<char>;
template FMT_API auto decimal_point_impl(locale_ref) -> char;
}  // namespace detail
FMT_END_NAMESPACE
