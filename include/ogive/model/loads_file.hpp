// A loads file: several loads for one scene, as CSV (the CLI's --loads-file): a header kind,value,a,b and
// one point, live or fill load a line. The format and its rules are specified in docs/file-formats.md.
// The loads returned keep the rules Scene::validate holds loads to (checked here, so that a message can
// name the line); errors throw std::invalid_argument "FILE:LINE: rule" (the header is line 1), or
// "FILE: rule" for a file that cannot be read.
#pragma once

#include <iosfwd>
#include <string>

#include "ogive/model/scene.hpp"

namespace ogive {

inline constexpr std::size_t kMaxLoadsInFile = 1000;

Loads read_loads_file(const std::string& path);
Loads parse_loads(std::istream& in, const std::string& name_for_messages);

}  // namespace ogive
