#pragma once
// The JSON names of the settings' enums, indexed by the enumerator: the one list that
// parsing, printing and the allowed-values table all read.
namespace shadowmap::names {

inline constexpr const char* kVariants[] = {"standard", "woo", "backface", "none", "volume"};
inline constexpr const char* kDepthFormats[] = {"d16", "d24", "d32f"};
inline constexpr const char* kFilters[] = {"nearest", "pcf", "pcss", "vsm", "evsm"};
inline constexpr const char* kProjections[] = {"uniform", "lispsm"};

} // namespace shadowmap::names
