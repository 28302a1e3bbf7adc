// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "bench/jobs.h"

#include <fstream>

#include <nlohmann/json.hpp>

#include "core/input_error.h"

namespace archgeo {

std::string JobLine(const BenchJob& job) {
  nlohmann::json settings = nlohmann::json::array();
  for (const auto& [key, value] : job.settings) settings.push_back({key, value});
  const nlohmann::json line = {{"spec", job.spec},     {"mesh", job.mesh},
                               {"settings", settings}, {"repeat", job.repeat},
                               {"record", job.record}};
  return line.dump() + "\n";  // dump() without indentation: one line
}

BenchJob ReadJob(const std::string& path, int k) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "--run-jobs", "cannot open the job file");
  if (k < 1) throw InputError(path, 0, "--job", "give the job to run, from 1 (--job K)");
  std::string text;
  int lines = 0;
  for (std::string line; lines < k && std::getline(in, line);) {
    ++lines;
    text = line;
  }
  if (lines < k) {
    throw InputError(path, 0, "--job", "no job " + std::to_string(k) + " (the file has " +
                                           std::to_string(lines) + ")");
  }
  BenchJob job;
  try {
    const nlohmann::json j = nlohmann::json::parse(text);
    job.spec = j.at("spec").get<std::string>();
    job.mesh = j.at("mesh").get<std::string>();
    for (const nlohmann::json& s : j.at("settings")) {
      job.settings.push_back({s.at(0).get<std::string>(), s.at(1).get<std::string>()});
    }
    job.repeat = j.at("repeat").get<int>();
    job.record = j.at("record").get<std::string>();
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path, k, "--job", std::string("not a job of archgeo bench --emit-jobs: ") + e.what());
  }
  if (job.repeat < 1) throw InputError(path, k, "--job", "the repeat's number must be at least 1");
  return job;
}

}  // namespace archgeo
