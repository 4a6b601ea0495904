#pragma once
// How a module that cannot be loaded is reported, alike in this process and in a controller host.
#include <string>

namespace frob::course {

/// Why `source`'s module cannot be loaded, from the loader's message (with C++ names demangled);
/// an empty message means the module loaded but declares no controller.
[[nodiscard]] std::string loadError(const std::string& source, const std::string& loaderMessage);

}  // namespace frob::course
