// Opening an input file, with an InputError that names the file when it is
// missing, a directory, or unreadable (a stream opened on a directory
// "succeeds" and fails later with the C library's words, without the name).
#pragma once

#include <fstream>
#include <string>

namespace dartcheck {

std::ifstream open_input(const std::string& file, std::ios::openmode mode = std::ios::in);

}  // namespace dartcheck
