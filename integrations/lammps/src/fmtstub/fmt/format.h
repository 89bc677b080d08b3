/*
 * Declaration-only stand-in for <fmt/format.h>.
 *
 * Debian 12's liblammps-dev installs LAMMPS headers that include "fmt/format.h"
 * but does not install LAMMPS's bundled {fmt} library headers.  The installed
 * headers only *name* three {fmt} entities: in the declarations of the
 * formatting overloads of Error::all/one/warning/message and utils::logmesg.
 * The plugin never calls those overloads (it formats its own messages and calls
 * the std::string overloads), so declarations are all that is needed to compile.
 * Written for this project; not a copy of {fmt}.
 */
#ifndef HERTZDAMP_LAMMPS_FMT_STANDIN_H
#define HERTZDAMP_LAMMPS_FMT_STANDIN_H
namespace fmt {
class string_view;
class format_args;
template <typename... Args, typename S> int make_args_checked(const S &, const Args &...);
}    // namespace fmt
#endif
