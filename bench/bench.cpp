// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "bench/bench.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <system_error>

#include "bench/child.h"
#include "bench/jobs.h"
#include "core/format_number.h"
#include "core/input_error.h"
#include "io/output_files.h"
#include "problems/spec/spec.h"

namespace archgeo {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using Settings_ = std::vector<std::pair<std::string, std::string>>;

std::string Trim(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

// 'key=[a,b,c]' or 'key=a'.
std::pair<std::string, std::vector<std::string>> ParseVary(const std::string& text) {
  const size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw InputError("", 0, "--vary", "'" + text + "': expected KEY=[VALUE,VALUE,...]");
  }
  const std::string key = Trim(text.substr(0, eq));
  std::string list = Trim(text.substr(eq + 1));
  std::vector<std::string> values;
  if (!list.empty() && list.front() == '[') {
    if (list.back() != ']') throw InputError("", 0, "--vary", "'" + text + "': missing ']'");
    list = list.substr(1, list.size() - 2);
    std::stringstream in(list);
    for (std::string v; std::getline(in, v, ',');) values.push_back(Trim(v));
  } else {
    values.push_back(list);
  }
  for (const std::string& v : values) {
    if (v.empty()) throw InputError("", 0, "--vary", "'" + text + "': an empty value");
  }
  return {key, values};
}

std::pair<std::string, std::string> ParseSet(const std::string& text) {
  const size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw InputError("", 0, "--set", "'" + text + "': expected KEY=VALUE");
  }
  return {Trim(text.substr(0, eq)), Trim(text.substr(eq + 1))};
}

std::string Absolute(const std::string& path) { return fs::absolute(path).lexically_normal().string(); }

// Single-quoted for a POSIX shell.
std::string Quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// A path as a YAML double-quoted scalar, for `--set KEY=VALUE` (whose value
// is YAML): every character kept, '#', ': ', quotes and line breaks included.
std::string YamlQuoted(const std::string& path) {
  std::string out = "\"";
  for (const char c : path) {
    if (c == '\\' || c == '"') {
      out += std::string("\\") + c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\x%02x", unsigned(static_cast<unsigned char>(c)));
      out += escape;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string ReadText(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The first line of `text` that contains `marker` ("" if none).
std::string LineWith(const std::string& text, const std::string& marker) {
  std::stringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.find(marker) != std::string::npos) return line;
  }
  return "";
}

std::string LastLine(const std::string& text) {
  std::stringstream in(text);
  std::string last;
  for (std::string line; std::getline(in, line);) {
    if (!Trim(line).empty()) last = line;
  }
  return last;
}

// The spec read with `mesh` (bad spec or mesh: InputError, as `solve` says it).
ProblemSpec Read(const std::string& spec, const std::string& mesh,
                 const Settings_& settings = {}) {
  std::vector<std::string> overrides = {"mesh=" + YamlQuoted(mesh)};
  for (const auto& [k, v] : settings) overrides.push_back(k + "=" + v);
  return ReadSpec(spec, overrides);
}

std::string Number(double x, const char* format = "%.4g") { return FormatNumber(format, x); }

std::string SettingsText(const json& settings) {
  std::string text;
  for (const auto& [k, v] : settings.items()) {
    text += (text.empty() ? "" : " ") + k + "=" + v.get<std::string>();
  }
  return text.empty() ? "(spec)" : text;
}

// The table, CSV and JSON of merged rows.
std::vector<std::string> Columns(const json& rows) {
  std::vector<std::string> measures;
  for (const json& r : rows) {
    for (const auto& [k, v] : r["measures"].items()) {
      if (std::find(measures.begin(), measures.end(), k) == measures.end()) measures.push_back(k);
    }
  }
  return measures;
}

std::string Csv(const json& rows) {
  const std::vector<std::string> measures = Columns(rows);
  std::vector<std::string> keys;
  for (const json& r : rows) {
    for (const auto& [k, v] : r["settings"].items()) {
      if (std::find(keys.begin(), keys.end(), k) == keys.end()) keys.push_back(k);
    }
  }
  auto cell = [](std::string s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
  };
  std::string out = "mesh";
  for (const std::string& k : keys) out += "," + k;
  out += ",repeats,exit_code,wall_median_s,wall_min_s,wall_max_s,evaluation_s,linear_solver_s,"
         "solver_s,iterations,peak_memory_mb,tolerance_met,objective";
  for (const std::string& m : measures) out += "," + m;
  out += ",message\n";
  for (const json& r : rows) {
    out += cell(r["mesh"]);
    for (const std::string& k : keys) out += "," + cell(r["settings"].value(k, ""));
    out += "," + std::to_string(r["repeats"].get<int>()) + "," +
           std::to_string(r["exit_code"].get<int>());
    for (const char* k : {"wall_median_s", "wall_min_s", "wall_max_s", "evaluation_s",
                          "linear_solver_s", "solver_s"}) {
      out += "," + (r[k].is_null() ? std::string() : Number(r[k].get<double>(), "%.6g"));
    }
    out += "," + (r["iterations"].is_null() ? std::string() : std::to_string(r["iterations"].get<int>()));
    out += "," + Number(r["peak_memory_mb"].get<double>(), "%.1f");
    out += "," + (r["tolerance_met"].is_null() ? std::string()
                                                : std::string(r["tolerance_met"].get<bool>() ? "true" : "false"));
    out += "," + (r["objective"].is_null() ? std::string() : Number(r["objective"].get<double>(), "%.10g"));
    for (const std::string& m : measures) {
      out += "," + (r["measures"].contains(m) ? Number(r["measures"][m].get<double>(), "%.6g") : "");
    }
    out += "," + cell(r["message"]) + "\n";
  }
  return out;
}

std::string Table(const json& rows) {
  const std::vector<std::string> measures = Columns(rows);
  std::vector<std::vector<std::string>> cells = {{"mesh", "settings", "exit", "wall s (min-max)",
                                                  "eval s", "linear s", "iter", "MB", "tol"}};
  for (const std::string& m : measures) cells[0].push_back(m);
  for (const json& r : rows) {
    std::vector<std::string> c = {fs::path(r["mesh"].get<std::string>()).filename().string(),
                                  SettingsText(r["settings"]), std::to_string(r["exit_code"].get<int>())};
    c.push_back(r["wall_median_s"].is_null()
                    ? "-"
                    : Number(r["wall_median_s"].get<double>(), "%.3f") + " (" +
                          Number(r["wall_min_s"].get<double>(), "%.3f") + "-" +
                          Number(r["wall_max_s"].get<double>(), "%.3f") + ")");
    for (const char* k : {"evaluation_s", "linear_solver_s"}) {
      c.push_back(r[k].is_null() ? "-" : Number(r[k].get<double>(), "%.3f"));
    }
    c.push_back(r["iterations"].is_null() ? "-" : std::to_string(r["iterations"].get<int>()));
    c.push_back(Number(r["peak_memory_mb"].get<double>(), "%.0f"));
    c.push_back(r["tolerance_met"].is_null() ? "-" : (r["tolerance_met"].get<bool>() ? "met" : "missed"));
    for (const std::string& m : measures) {
      c.push_back(r["measures"].contains(m) ? Number(r["measures"][m].get<double>(), "%.3e") : "-");
    }
    cells.push_back(c);
  }
  std::vector<size_t> width(cells[0].size(), 0);
  for (const auto& row : cells) {
    for (size_t i = 0; i < row.size(); ++i) width[i] = std::max(width[i], row[i].size());
  }
  std::string out;
  for (size_t r = 0; r < cells.size(); ++r) {
    for (size_t i = 0; i < cells[r].size(); ++i) {
      out += cells[r][i] + std::string(width[i] - cells[r][i].size() + 2, ' ');
    }
    out += "\n";
    if (r == 0) out += std::string(out.size() - 1, '-') + "\n";
  }
  for (const json& r : rows) {
    if (!r["message"].get<std::string>().empty()) {
      out += fs::path(r["mesh"].get<std::string>()).filename().string() + ", " +
             SettingsText(r["settings"]) + ": " + r["message"].get<std::string>() + "\n";
    }
  }
  return out;
}

// Output files of text, staged when added (an input, a folder, a FIFO or a
// device is refused before anything runs) and put in place together by
// Commit(): a failure leaves every previous file as it was.
class StagedTexts {
 public:
  explicit StagedTexts(std::vector<std::string> inputs) : staged_(std::move(inputs)) {}

  void Add(const std::string& target, const std::string& key) {
    files_.push_back({staged_.Stage(target, key), target, key});
  }

  // texts[i] goes to the i-th file added.
  void Commit(const std::vector<std::string>& texts) {
    for (size_t i = 0; i < files_.size(); ++i) {
      try {
        WriteTextFile(files_[i].temporary, texts.at(i), files_[i].key);
      } catch (const InputError& e) {
        throw InputError(files_[i].target, 0, files_[i].key, e.message());
      }
    }
    staged_.Commit();
  }

 private:
  struct File {
    std::string temporary, target, key;
  };
  StagedOutputs staged_;
  std::vector<File> files_;
};

// --out R.csv and R.json beside it: names that cannot be equal.
void AddRowFiles(StagedTexts& outputs, const std::string& csv) {
  if (csv.empty()) return;
  std::string extension = fs::path(csv).extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (extension != ".csv") {
    throw InputError(csv, 0, "--out", "must end in .csv (the rows go to it as CSV and, as JSON, "
                                      "to the same name ending in .json)");
  }
  outputs.Add(csv, "--out");
  outputs.Add(fs::path(csv).replace_extension(".json").string(), "--out");
}

std::vector<std::string> RowTexts(const json& rows) { return {Csv(rows), rows.dump(2) + "\n"}; }

// Every file the runs read: the spec, what it reads with each mesh (the
// mesh included) and the archgeo binary. No output may name one.
std::vector<std::string> BenchInputs(const std::string& spec, const std::vector<std::string>& meshes,
                                     const std::string& self) {
  std::vector<std::string> inputs = {spec, self};
  for (const std::string& mesh : meshes) {
    const std::vector<std::string> read = Read(spec, mesh).InputFiles();
    inputs.insert(inputs.end(), read.begin(), read.end());
    inputs.push_back(mesh);
  }
  return inputs;
}

// The validated plan: every combination of the --vary values, in order.
std::vector<Settings_> Combinations(const BenchRequest& q) {
  std::vector<Settings_> plan = {{}};
  for (const std::string& text : q.vary) {
    const auto [key, values] = ParseVary(text);
    std::vector<Settings_> next;
    for (const Settings_& s : plan) {
      for (const std::string& v : values) {
        Settings_ t = s;
        t.push_back({key, v});
        next.push_back(t);
      }
    }
    plan = next;
  }
  return plan;
}

void Validate(const BenchRequest& q, const std::vector<Settings_>& plan) {
  if (q.meshes.empty()) throw InputError("", 0, "--mesh", "give at least one --mesh");
  if (q.repeat < 1) throw InputError("", 0, "--repeat", "must be at least 1");
  for (const std::string& m : q.meshes) {
    if (!fs::is_regular_file(m)) throw InputError(m, 0, "--mesh", "no such file");
  }
  const ProblemSpec spec = Read(q.spec, q.meshes.front());
  for (const Settings_& s : plan) {
    for (const auto& [key, value] : s) {
      if (!spec.settings.schema().Find(key)) {
        throw InputError("", 0, "--vary",
                         "'" + key + "' is not a key of this spec's problem (archgeo spec " +
                             spec.settings.String("problem") + " --keys lists them)");
      }
    }
  }
}

}  // namespace

double Median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n == 0 ? 0.0 : (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}

json RunOnce(const std::string& self, const std::string& spec, const std::string& mesh,
             const Settings_& settings, int repeat) {
  json record = {{"mesh", Absolute(mesh)}, {"settings", json::object()}, {"repeat", repeat}};
  for (const auto& [k, v] : settings) record["settings"][k] = v;
  const ScratchFolder folder;
  const fs::path scratch = folder.path();

  std::vector<std::string> args = {self, "solve", Absolute(spec), "--quiet", "--set",
                                   "mesh=" + YamlQuoted(Absolute(mesh))};
  for (const auto& [k, v] : settings) args.insert(args.end(), {"--set", k + "=" + v});
  // Every output the spec writes goes into the scratch folder.
  try {
    const ProblemSpec read = Read(spec, mesh);
    for (const Key& k : read.settings.schema().keys()) {
      if (k.type != Type::kOutputPath || k.name == "output.report") continue;
      const std::string path = read.settings.String(k.name);
      if (!path.empty()) {
        args.insert(args.end(),
                    {"--set", k.name + "=" + YamlQuoted((scratch / fs::path(path).filename()).string())});
      }
    }
  } catch (const InputError&) {
    // The run itself reports it.
  }
  const fs::path report = scratch / "report.json";
  args.insert(args.end(), {"--set", "output.report=" + YamlQuoted(report.string())});

  const ChildOutcome child =
      RunChild(args, (scratch / "stdout.txt").string(), (scratch / "stderr.txt").string());
  const int exit_code = child.exit_code;
  record["exit_code"] = exit_code;
  record["wall_s"] = child.wall_s;
  record["peak_memory_mb"] = child.peak_memory_mb;
  record["command"] = args;

  const std::string out = ReadText(scratch / "stdout.txt"), err = ReadText(scratch / "stderr.txt");
  std::string message;
  if (exit_code != 0) {
    message = LineWith(err, "archgeo: ");
    if (message.empty()) message = LineWith(out, "NOT met");     // exit 4: which tolerance
    if (message.empty()) message = LineWith(out, "WARNING");
    if (message.empty()) message = LastLine(err);
  }
  record["message"] = message;
  if (fs::is_regular_file(report)) {
    try {
      const json r = json::parse(ReadText(report));
      const json& seconds = r.at("seconds");
      record["solver_s"] = seconds.value("solver", 0.0);
      record["evaluation_s"] = seconds.value("jacobian", 0.0);
      record["linear_solver_s"] = seconds.value("linear_solver", 0.0);
      record["iterations"] = r.at("iterations").value("inner", 0);
      record["objective"] = r.at("objective").value("total", 0.0);
      bool met = true;
      json measures = json::object();
      for (const auto& [name, t] : r.at("tolerances").items()) {
        met = met && t.value("met", false);
        const std::string measure = name.substr(name.find('.') + 1);
        if (r.at("after").contains(measure) && r["after"][measure].is_number()) {
          measures[measure] = r["after"][measure];
        }
      }
      record["tolerance_met"] = met;
      record["measures"] = measures;
    } catch (const json::exception& e) {
      record["message"] = std::string("unreadable report: ") + e.what();
    }
  }
  return record;
}

json MergeRecords(const std::vector<json>& records) {
  std::vector<std::pair<std::string, json>> order;
  std::map<std::string, std::vector<json>> groups;
  for (const json& r : records) {
    const std::string id = r["mesh"].get<std::string>() + "\n" + r["settings"].dump();
    if (!groups.count(id)) order.push_back({id, r});
    groups[id].push_back(r);
  }
  json rows = json::array();
  for (const auto& [id, first] : order) {
    const std::vector<json>& g = groups[id];
    json row = {{"mesh", first["mesh"]}, {"settings", first["settings"]},
                {"repeats", int(g.size())}, {"exit_code", 0}, {"message", ""}};
    std::vector<double> wall, eval, linear, ceres;
    double memory = 0;
    for (const json& r : g) {
      if (r["exit_code"].get<int>() != 0 && row["exit_code"].get<int>() == 0) {
        row["exit_code"] = r["exit_code"];
        row["message"] = r["message"];
      }
      wall.push_back(r["wall_s"].get<double>());
      memory = std::max(memory, r["peak_memory_mb"].get<double>());
      if (r.contains("solver_s")) {
        ceres.push_back(r["solver_s"].get<double>());
        eval.push_back(r["evaluation_s"].get<double>());
        linear.push_back(r["linear_solver_s"].get<double>());
      }
    }
    row["wall_median_s"] = Median(wall);
    row["wall_min_s"] = *std::min_element(wall.begin(), wall.end());
    row["wall_max_s"] = *std::max_element(wall.begin(), wall.end());
    row["peak_memory_mb"] = memory;
    row["solver_s"] = ceres.empty() ? json() : json(Median(ceres));
    row["evaluation_s"] = eval.empty() ? json() : json(Median(eval));
    row["linear_solver_s"] = linear.empty() ? json() : json(Median(linear));
    // The quality figures are the same in every repeat (deterministic runs).
    row["iterations"] = first.contains("iterations") ? first["iterations"] : json();
    row["objective"] = first.contains("objective") ? first["objective"] : json();
    row["tolerance_met"] = first.contains("tolerance_met") ? first["tolerance_met"] : json();
    row["measures"] = first.value("measures", json::object());
    rows.push_back(row);
  }
  return rows;
}

namespace {

// Which mode the options ask for; combinations that would ignore an option
// are refused.
void CheckModes(const BenchRequest& q) {
  if (!q.out.empty() && (!q.emit_jobs.empty() || !q.record.empty() || !q.run_jobs.empty())) {
    throw InputError(q.out, 0, "--out", "not with --emit-jobs, --record or --run-jobs (their "
                                        "records are merged by --collect DIR --out R.csv)");
  }
  if (q.job != 0 && q.run_jobs.empty()) throw InputError("", 0, "--job", "only with --run-jobs FILE");
  if (!q.run_jobs.empty() && (!q.spec.empty() || !q.meshes.empty())) {
    throw InputError(q.run_jobs, 0, "--run-jobs", "takes no SPEC or --mesh (the job names them)");
  }
}

std::string Collect(const BenchRequest& q) {
  if (!fs::is_directory(q.collect)) throw InputError(q.collect, 0, "--collect", "not a folder");
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(q.collect)) {
    if (e.path().extension() == ".json") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  if (files.empty()) throw InputError(q.collect, 0, "--collect", "no records (*.json) in it");
  std::vector<std::string> inputs;
  for (const fs::path& f : files) inputs.push_back(f.string());
  StagedTexts outputs(inputs);
  AddRowFiles(outputs, q.out);
  std::vector<json> records;
  for (const fs::path& f : files) {
    try {
      records.push_back(json::parse(ReadText(f)));
      (void)records.back().at("exit_code");
    } catch (const json::exception& e) {
      throw InputError(f.string(), 0, "--collect", std::string("not a bench record: ") + e.what());
    }
  }
  const json rows = MergeRecords(records);
  if (!q.out.empty()) outputs.Commit(RowTexts(rows));
  return Table(rows) + (q.out.empty() ? "" : "wrote " + q.out + "\n");
}

// One run into one record (--record, or a job of --run-jobs). `key` names
// the record's option; `also_read` are inputs beyond the run's (the job file).
std::string RecordRun(const std::string& self, const BenchJob& job, const std::string& key,
                      const std::vector<std::string>& also_read) {
  BenchRequest check;
  check.spec = job.spec;
  check.meshes = {job.mesh};
  check.repeat = job.repeat;
  Validate(check, {job.settings});
  std::vector<std::string> inputs = BenchInputs(job.spec, {job.mesh}, self);
  inputs.insert(inputs.end(), also_read.begin(), also_read.end());
  // Made here, not by Stage(): a job that fails never removes the folder
  // other jobs write into.
  std::error_code ignored;  // Stage() reports a folder that cannot be made
  fs::create_directories(fs::path(job.record).parent_path(), ignored);
  StagedTexts output(inputs);
  output.Add(job.record, key);
  const json record = RunOnce(self, job.spec, job.mesh, job.settings, job.repeat);
  output.Commit({record.dump(2) + "\n"});
  return "wrote " + job.record + " (exit code " + std::to_string(record["exit_code"].get<int>()) + ")\n";
}

std::string EmitJobs(const BenchRequest& q, const std::vector<Settings_>& plan) {
  fs::path records = q.records;
  if (records.empty()) records = fs::path(q.emit_jobs).replace_extension("").string() + "_runs";
  records = Absolute(records.string());
  if (fs::exists(records) && !fs::is_directory(records)) {
    throw InputError(records.string(), 0, "--records", "exists and is not a folder");
  }
  StagedTexts output(BenchInputs(q.spec, q.meshes, q.self));
  output.Add(q.emit_jobs, "--emit-jobs");
  std::string jobs;
  int index = 0;
  for (const Settings_& s : plan) {
    for (const std::string& mesh : q.meshes) {
      ++index;
      for (int r = 1; r <= q.repeat; ++r) {
        char name[64];
        std::snprintf(name, sizeof name, "run-%04d-r%d.json", index, r);
        jobs += JobLine({Absolute(q.spec), Absolute(mesh), s, r, (records / name).string()});
      }
    }
  }
  output.Commit({jobs});
  const std::string count = std::to_string(index * q.repeat);
  return "wrote " + count + " jobs to " + q.emit_jobs + "; each writes its record into " +
         records.string() + "\nrun them (job K is `archgeo bench --run-jobs JOBS --job K`), e.g.:\n" +
         "  seq " + count + " | xargs -P 2 -n 1 " + Quote(q.self) + " bench --run-jobs " +
         Quote(Absolute(q.emit_jobs)) + " --job\nthen: archgeo bench --collect " +
         Quote(records.string()) + " --out results.csv\n";
}

}  // namespace

std::string RunBench(const BenchRequest& q) {
  CheckModes(q);
  if (!q.collect.empty()) return Collect(q);
  if (!q.run_jobs.empty()) {
    const std::string jobs = Absolute(q.run_jobs);
    return RecordRun(q.self, ReadJob(q.run_jobs, q.job), "--run-jobs", {jobs});
  }
  if (q.spec.empty()) throw InputError("", 0, "SPEC", "give a spec (or --collect DIR)");
  if (!q.record.empty()) {
    if (q.meshes.size() != 1) throw InputError("", 0, "--mesh", "--record runs one mesh");
    BenchJob job{q.spec, q.meshes[0], {}, q.repeat, q.record};
    for (const std::string& s : q.sets) job.settings.push_back(ParseSet(s));
    return RecordRun(q.self, job, "--record", {});
  }

  const std::vector<Settings_> plan = Combinations(q);
  Validate(q, plan);
  if (!q.emit_jobs.empty()) return EmitJobs(q, plan);

  StagedTexts outputs(BenchInputs(q.spec, q.meshes, q.self));
  AddRowFiles(outputs, q.out);
  std::vector<json> records;
  const int runs = int(plan.size() * q.meshes.size()) * q.repeat;
  for (const Settings_& s : plan) {
    for (const std::string& mesh : q.meshes) {
      for (int r = 1; r <= q.repeat; ++r) {
        const std::string run = "run " + std::to_string(records.size() + 1) + " of " +
                                std::to_string(runs) + ": " + fs::path(mesh).filename().string();
        if (q.progress) {
          std::string note = run;
          for (const auto& [key, value] : s) note += ", " + key + "=" + value;
          q.progress(note + (q.repeat > 1 ? ", repeat " + std::to_string(r) : ""));
        }
        records.push_back(RunOnce(q.self, q.spec, mesh, s, r));
        if (q.progress) {
          q.progress(run + " done: exit code " +
                     std::to_string(records.back().value("exit_code", -1)) + ", " +
                     Number(records.back().value("wall_s", 0.0), "%.2f") + " s");
        }
      }
    }
  }
  const json rows = MergeRecords(records);
  if (!q.out.empty()) outputs.Commit(RowTexts(rows));
  return Table(rows) + (q.out.empty() ? "" : "wrote " + q.out + "\n");
}

}  // namespace archgeo
