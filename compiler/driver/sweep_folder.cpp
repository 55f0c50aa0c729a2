#include "compiler/driver/sweep_folder.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <filesystem>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "lang/source/source_manager.h"
#include "output/atomic_file.h"
#include "runtime/run/fnv1a.h"

namespace sled::driver {
namespace {

using Json = nlohmann::json;
namespace fs = std::filesystem;

bool WriteJson(const fs::path& path, const Json& json, std::string* error) {
  return runtime::ReplaceFile(path.string(), json.dump(1) + "\n", error);
}

std::optional<Json> ReadJson(const fs::path& path, std::string* error) {
  std::string why;
  const auto text = lang::ReadFile(path.string(), &why);
  if (!text) {
    if (error)
      *error = fmt::format("cannot read `{}`{}", path.string(), why.empty() ? "" : ": " + why);
    return std::nullopt;
  }
  Json json = Json::parse(*text, nullptr, /*allow_exceptions=*/false);
  if (json.is_discarded() || !json.is_object()) {
    if (error) *error = fmt::format("`{}` is no JSON object", path.string());
    return std::nullopt;
  }
  return json;
}

}  // namespace

bool SweepManifest::SameSweep(const SweepManifest& other) const {
  auto same_files = [](const std::vector<SweepFile>& a, const std::vector<SweepFile>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (a[i].path != b[i].path || a[i].digest != b[i].digest) return false;
    }
    return true;
  };
  if (scene != other.scene || !same_files(files, other.files) ||
      run_arguments != other.run_arguments || variables.size() != other.variables.size() ||
      runs.size() != other.runs.size()) {
    return false;
  }
  for (std::size_t v = 0; v < variables.size(); ++v) {
    if (variables[v].name != other.variables[v].name ||
        variables[v].unit != other.variables[v].unit) {
      return false;
    }
  }
  for (std::size_t r = 0; r < runs.size(); ++r) {
    if (runs[r].values != other.runs[r].values || runs[r].folder != other.runs[r].folder) {
      return false;
    }
  }
  return true;
}

bool WriteManifest(const std::string& directory, const SweepManifest& manifest,
                   std::string* error) {
  Json json;
  json["format"] = 1;
  json["scene"] = manifest.scene;
  json["files"] = Json::array();
  for (const SweepFile& file : manifest.files) {
    json["files"].push_back({{"path", file.path}, {"fnv1a", file.digest}});
  }
  json["run_arguments"] = manifest.run_arguments;
  json["design"] = {{"method", manifest.method},
                    {"seed", manifest.seed},
                    {"vary", manifest.vary},
                    {"file", manifest.design_file}};
  json["variables"] = Json::array();
  for (const SweepVariable& variable : manifest.variables) {
    json["variables"].push_back({{"name", variable.name}, {"unit", variable.unit}});
  }
  json["runs"] = Json::array();
  for (const SweepRun& run : manifest.runs) {
    json["runs"].push_back(
        {{"folder", run.folder}, {"numbers", run.numbers}, {"values", run.values}});
  }
  return WriteJson(fs::path(directory) / kManifestName, json, error);
}

std::optional<SweepManifest> ReadManifest(const std::string& directory, std::string* error) {
  const auto json = ReadJson(fs::path(directory) / kManifestName, error);
  if (!json) return std::nullopt;
  try {
    SweepManifest manifest;
    if (json->at("format").get<int>() != 1) throw std::runtime_error("an unknown format");
    manifest.scene = json->at("scene").get<std::string>();
    for (const Json& file : json->at("files")) {
      manifest.files.push_back(
          {file.at("path").get<std::string>(), file.at("fnv1a").get<std::string>()});
    }
    manifest.run_arguments = json->at("run_arguments").get<std::vector<std::string>>();
    const Json& design = json->at("design");
    manifest.method = design.at("method").get<std::string>();
    manifest.seed = design.at("seed").get<unsigned long long>();
    manifest.vary = design.at("vary").get<std::vector<std::string>>();
    manifest.design_file = design.at("file").get<std::string>();
    for (const Json& variable : json->at("variables")) {
      manifest.variables.push_back(
          {variable.at("name").get<std::string>(), variable.at("unit").get<std::string>()});
    }
    for (const Json& run : json->at("runs")) {
      SweepRun entry;
      entry.folder = run.at("folder").get<std::string>();
      entry.numbers = run.at("numbers").get<std::vector<double>>();
      entry.values = run.at("values").get<std::vector<std::string>>();
      if (entry.values.size() != manifest.variables.size() ||
          entry.numbers.size() != manifest.variables.size() || entry.folder.empty() ||
          fs::path(entry.folder).is_absolute() || entry.folder.find("..") != std::string::npos) {
        throw std::runtime_error("a run that does not fit the variables");
      }
      manifest.runs.push_back(std::move(entry));
    }
    return manifest;
  } catch (const std::exception& problem) {
    if (error) {
      *error = fmt::format("`{}` is not a sweep record sled can read ({})",
                           (fs::path(directory) / kManifestName).string(), problem.what());
    }
    return std::nullopt;
  }
}

std::string FileDigest(const std::string& path) {
  const auto text = lang::ReadFile(path);
  return text ? fmt::format("{:016x}", runtime::Fnv1a(*text)) : std::string();
}

std::string ChangedFiles(const SweepManifest& manifest) {
  std::string changed;
  for (const SweepFile& file : manifest.files) {
    if (FileDigest(file.path) != file.digest) {
      changed += fmt::format("{}`{}`", changed.empty() ? "" : ", ", file.path);
    }
  }
  return changed;
}

std::string RunFolderName(std::size_t run, std::size_t runs) {
  const std::size_t width = std::max<std::size_t>(4, fmt::format("{}", runs - 1).size());
  return fmt::format("runs/{:0{}}", run, width);
}

bool WriteRunStatus(const std::string& run_directory, const RunStatus& status, std::string* error) {
  Json json = {{"status", status.status},
               {"exit_code", status.exit_code},
               {"signal", status.signal},
               {"wall_seconds", status.wall_seconds},
               {"message", status.message}};
  return WriteJson(fs::path(run_directory) / "status.json", json, error);
}

std::optional<RunStatus> ReadRunStatus(const std::string& run_directory) {
  const auto json = ReadJson(fs::path(run_directory) / "status.json", nullptr);
  if (!json) return std::nullopt;
  try {
    RunStatus status;
    status.status = json->at("status").get<std::string>();
    status.exit_code = json->at("exit_code").get<int>();
    status.signal = json->at("signal").get<int>();
    status.wall_seconds = json->at("wall_seconds").get<double>();
    status.message = json->at("message").get<std::string>();
    return status;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

bool LockSweepFolder(const std::string& directory, std::string* error) {
  const std::string path = (fs::path(directory) / ".lock").string();
  // Kept open (and so locked) until the process ends.
  const int fd = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) {
    *error = fmt::format("cannot create `{}`", path);
    return false;
  }
  if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
    close(fd);
    *error =
        fmt::format("another `sled sweep` is running in `{}`; wait for it, or stop it", directory);
    return false;
  }
  return true;
}

}  // namespace sled::driver
