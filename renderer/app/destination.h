// Where a command will write, checked before it starts any work, so that an hour of rendering or fitting
// never ends in "cannot write": each check throws InputError naming the option and the path.
#pragma once

#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>

namespace glossy::app {

enum class Folder {
  Create,  // missing folders on the way are created when writing (render, sheet)
  Exist,   // the file's folder must already exist (fit -o: a typo in the folder is more likely than a wish)
};

// An output file: a non-empty path that is not a folder, whose extension is one of `extensions` (".exr"),
// whose folder exists (or, with Folder::Create, whose nearest existing ancestor is a folder) and is writable.
void checkOutputFile(const std::filesystem::path& path, std::string_view option,
                     std::initializer_list<std::string_view> extensions, Folder folder);

// An output folder: a non-empty path that is a writable folder, or that can be created under a writable one.
void checkOutputFolder(const std::filesystem::path& path, std::string_view option);

}  // namespace glossy::app
