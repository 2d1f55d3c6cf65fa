// Declaration of the table the build generates from data/eyes/*.json (cmake/embed_files.cmake):
// file name (e.g. "navarro.json") -> file text. The eye presets read their prescriptions from
// here so the program needs no install path to find its data.
#pragma once

#include <map>
#include <string>

namespace eyetrace::embedded {

const std::map<std::string, std::string>& files();

}  // namespace eyetrace::embedded
