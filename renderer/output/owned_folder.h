// A folder a command fills with files of its own — glossy plot's -o, glossy report's site — so that the
// command writes only files it creates and never deletes one it did not write. The folder carries a
// manifest, .glossy-manifest:
//   {"command": "glossy report", "files": ["index.html", "materials/chrome/index.html", ...]}
// listing every file glossy wrote there (paths relative to the folder). A run may fill a folder that is
// missing, empty, or whose manifest names the same command; any other folder is refused (a user's folder,
// `/`, another command's output). In its own folder a run replaces the files its manifest lists and leaves
// every other file alone: a file it would write that is there but not listed is refused, not overwritten.
//
// The manifest is written before the first file, listing the earlier files and the planned ones, and again
// at the end with the planned ones only, when the earlier files no longer planned are removed. So a run cut
// short (an error, a signal) leaves a folder whose every glossy file is listed, which the next run may
// replace; the files themselves are written atomically (renderer/util/atomic_file.h).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace glossy {

class OwnedFolder {
 public:
  inline static const char* const kManifest = ".glossy-manifest";

  // Checks, before any work, that `command` ("glossy plot") may fill `folder`. Throws InputError
  // "OPTION FOLDER: ..." when it is a file, a non-empty folder without the command's manifest, or holds a
  // manifest that is not one glossy writes.
  OwnedFolder(const std::filesystem::path& folder, std::string command, std::string option);

  const std::filesystem::path& root() const { return root_; }
  std::filesystem::path path(const std::string& file) const { return root_ / file; }

  // Before writing: checks each planned file (a relative path of plain names) — InputError when it is there
  // but not glossy's, or when a folder on its way is a symlink or a file — creates the folder and records
  // the earlier and the planned files in the manifest.
  void plan(const std::vector<std::string>& files);

  // After writing every planned file: the manifest lists them alone; the earlier files not planned again
  // are removed, with the folders that leaves empty.
  void finish();

 private:
  std::filesystem::path root_;
  std::string command_, option_;
  std::vector<std::string> earlier_, planned_;

  void writeManifest(const std::vector<std::string>& files) const;
  std::string where() const;
};

}  // namespace glossy
