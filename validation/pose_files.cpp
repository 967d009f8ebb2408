#include "pose_files.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>

namespace sscc::validation {

namespace {

bool is_mesh_file(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".off" || extension == ".obj" || extension == ".ply";
}

}  // namespace

std::vector<std::string> example_pose_files(const std::vector<std::string>& items) {
  std::vector<std::string> files;
  for (const std::string& item : items) {
    if (!std::filesystem::is_directory(item)) {
      files.push_back(item);
      continue;
    }
    std::vector<std::string> found;
    for (const auto& entry : std::filesystem::directory_iterator(item)) {
      if (entry.is_regular_file() && is_mesh_file(entry.path())) found.push_back(entry.path().string());
    }
    if (found.empty())
      throw std::invalid_argument("example poses: directory " + item + " holds no .off, .obj or .ply file");
    std::sort(found.begin(), found.end());
    files.insert(files.end(), found.begin(), found.end());
  }
  return files;
}

PoseSubspace pose_subspace_from_files(const TriangleMesh& reference, const std::vector<std::string>& items,
                                      const PcaOptions& options, std::ostream& progress) {
  const std::vector<std::string> files = example_pose_files(items);
  progress << "pca: reading " << files.size() << " example poses\n";
  const PoseSubspace subspace(reference, read_example_poses(reference, files), options);
  progress << "pca: " << subspace.component_variances().size() << " components, " << subspace.mode_count()
           << " kept, explaining " << subspace.explained_fraction() << " of the variance\n";
  return subspace;
}

}  // namespace sscc::validation
