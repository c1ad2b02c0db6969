// fmt's compiled part, built here as the static library rs_fmt: Debian's
// libfmt-dev ships fmt only as a shared library, and a shared libfmt pulls
// the shared libstdc++ into every process, which a statically linked
// `robotsim` avoids (its start-up: docs/performance.md, docs/install.md).
// fmt's implementation header defines the functions; the explicit
// instantiations below are the templates format.h declares `extern`, for
// char only (robotsim formats no wide strings). Nothing else in the tree
// includes fmt/format-inl.h.
#include <fmt/format-inl.h>

FMT_BEGIN_NAMESPACE
namespace detail {

template auto dragonbox::to_decimal(float x) noexcept -> dragonbox::decimal_fp<float>;
template auto dragonbox::to_decimal(double x) noexcept -> dragonbox::decimal_fp<double>;
template locale_ref::locale_ref(const std::locale& loc);
template auto locale_ref::get<std::locale>() const -> std::locale;
template auto thousands_sep_impl(locale_ref) -> thousands_sep_result<char>;
template auto decimal_point_impl(locale_ref) -> char;
template void buffer<char>::append(const char*, const char*);
template void vformat_to(buffer<char>&, string_view, basic_format_args<FMT_BUFFER_CONTEXT(char)>, locale_ref);

}  // namespace detail
FMT_END_NAMESPACE
