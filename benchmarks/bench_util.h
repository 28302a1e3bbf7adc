// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo benchmarks — shared helpers (header-only; every .cpp here is one
// program of build/benchmarks/archgeo_benchmarks, see program.h).
//
//   Solve(...)        one `archgeo solve` in process (ReadSpec + RunSpec), no outputs
//   RunProcess(...)   a subprocess with wall-clock and CPU time, peak RSS and a timeout
//   SolveCommand(...) `archgeo solve --quiet` as a subprocess, report read back
//   Table             a left-aligned text table
//   PrintMarkdown     rows as a Markdown table
#pragma once

#include <fcntl.h>
#include <glog/logging.h>
#include <nlohmann/json.hpp>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include "core/input_error.h"
#include "problems/commands/run.h"
#include "core/solver_options.h"
#include "problems/spec/spec.h"

namespace bench {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using Clock = std::chrono::steady_clock;

using Rows = std::vector<std::vector<std::string>>;

// `rows` (the first the header) as a Markdown table on stdout.
inline void PrintMarkdown(const Rows& rows) {
  for (size_t i = 0; i < rows.size(); ++i) {
    std::string line = "|";
    for (const std::string& cell : rows[i]) line += " " + cell + " |";
    std::cout << line << "\n";
    if (i == 0) {
      std::string rule = "|";
      for (size_t c = 0; c < rows[0].size(); ++c) rule += "---|";
      std::cout << rule << "\n";
    }
  }
}

inline std::string Source(const std::string& rel) {
  return std::string(ARCHGEO_SOURCE_DIR) + "/" + rel;
}
inline std::string Data(const std::string& name) {
  return fs::path(ARCHGEO_DATA_DIR + std::string("/") + name).lexically_normal().string();
}
inline double Seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

// glog as in tools/archgeo.cpp: errors only, to stderr.
inline void InitLogging(const char* argv0) {
  google::InitGoogleLogging(argv0);
  FLAGS_minloglevel = google::GLOG_ERROR;
  FLAGS_logtostderr = true;
}

// `--set KEY=VALUE` arguments of a benchmark program: added to every solve
// it runs (Solve, SolveCommand), e.g. `--set terms.dihedral_energy.weight=0`
// to see its acceptance fail without the energy it is about.
inline std::vector<std::string>& ExtraSets() {
  static std::vector<std::string> sets;
  return sets;
}

// An argument a benchmark program takes besides --set KEY=VALUE, and
// whether a value follows it.
struct Flag {
  std::string name;
  bool value = false;
};

// InitLogging, and the --set arguments taken out of argv (the rest is left
// for the program, in order). Any other argument must be one of `flags`
// (with its value where it takes one): otherwise the program prints its
// usage and exits with code 2 before running anything, so a misspelt
// option is never silently ignored.
inline std::vector<std::string> Init(int argc, char** argv, const std::vector<Flag>& flags = {}) {
  InitLogging(argv[0]);
  std::vector<std::string> rest;
  std::string usage;
  for (const Flag& f : flags) usage += " [" + f.name + (f.value ? " VALUE]" : "]");
  const auto refuse = [&](const std::string& why) {
    std::fprintf(stderr, "%s: %s\nusage: %s%s [--set KEY=VALUE]...\n", argv[0], why.c_str(),
                 argv[0], usage.c_str());
    std::exit(2);
  };
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--set") {
      if (i + 1 >= argc) refuse("--set needs KEY=VALUE");
      ExtraSets().push_back(argv[++i]);
      continue;
    }
    const auto f = std::find_if(flags.begin(), flags.end(), [&](const Flag& x) { return x.name == a; });
    if (f == flags.end()) refuse("unknown argument '" + a + "'");
    rest.push_back(a);
    if (f->value) {
      if (i + 1 >= argc) refuse(a + " needs a value");
      rest.push_back(argv[++i]);
    }
  }
  if (!ExtraSets().empty()) {
    std::printf("every run with:");
    for (const std::string& s : ExtraSets()) std::printf(" --set %s", s.c_str());
    std::printf("\n\n");
  }
  return rest;
}

// Ends the program with code 2 and a message naming the flag, its value and
// what it takes.
[[noreturn]] inline void RefuseValue(const char* argv0, const std::string& flag,
                                     const std::string& text, const char* expected) {
  std::fprintf(stderr, "%s: %s '%s': expected %s\n", argv0, flag.c_str(), text.c_str(), expected);
  std::exit(2);
}

// The value of a flag that takes a positive number of seconds (else RefuseValue).
inline double SecondsArgument(const char* argv0, const std::string& flag, const std::string& text) {
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !(x > 0) || !std::isfinite(x)) {
    RefuseValue(argv0, flag, text, "a positive number of seconds");
  }
  return x;
}

// The value of a flag that takes a count from 1 to 1000 (else RefuseValue).
inline int CountArgument(const char* argv0, const std::string& flag, const std::string& text) {
  char* end = nullptr;
  const long x = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || x < 1 || x > 1000) {
    RefuseValue(argv0, flag, text, "a whole number from 1 to 1000");
  }
  return int(x);
}

// A scratch folder under $TMPDIR (or /tmp), created on first use.
inline fs::path Scratch() {
  static const fs::path dir = [] {
    fs::path d = fs::temp_directory_path() / ("archgeo_bench_" + std::to_string(getuid()));
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

// f(); bad input (an InputError: a --set naming an unknown key, say) ends
// the program as it ends `archgeo solve`: the message and exit code 2.
template <class F>
auto ExitOnInputError(const F& f) -> decltype(f()) {
  try {
    return f();
  } catch (const archgeo::InputError& e) {
    std::cout << std::flush;
    std::cerr << "error: " << e.what() << "\n";
    std::exit(2);
  }
}

// One solve in this process: the spec with `overrides`, no output files but
// `outputs` (KEY=PATH sets, e.g. output.layout=...).
// Returns the run report plus "wall_seconds" (around RunSpec) and "exit_code".
// `progress` is called once per Ceres iteration, on the solving thread.
// Bad input (a --set naming an unknown key, say) ends the program as
// `archgeo solve` would: the message, exit code 2 (SolveCommand too).
inline Json Solve(const std::string& spec_path, const std::vector<std::string>& overrides,
                  const archgeo::ProgressSink& progress = {},
                  const std::vector<std::string>& outputs = {}) {
  std::vector<std::string> all = overrides;
  all.insert(all.end(), ExtraSets().begin(), ExtraSets().end());
  all.push_back("output.mesh=");  // no output files
  all.push_back("output.report=");
  all.insert(all.end(), outputs.begin(), outputs.end());
  const auto start = Clock::now();
  const archgeo::RunResult run =
      ExitOnInputError([&] { return archgeo::RunSpec(archgeo::ReadSpec(spec_path, all), progress); });
  Json report = run.report;
  report["wall_seconds"] = Seconds(start);
  report["exit_code"] = run.exit_code;
  return report;
}

struct ProcessResult {
  int exit_code = -1;  // -1: killed by a signal (or the timeout)
  bool timed_out = false;
  double seconds = 0;     // wall clock, fork to reap
  double cpu_seconds = 0; // user + system CPU time of the child (wait4 rusage): the
                          // measure to compare on a shared machine
  double max_rss_mb = 0;  // peak resident set (wait4 ru_maxrss)
};

// Runs argv[0] with `argv` (PATH not searched), stdout and stderr to `log`;
// killed after `timeout` seconds if > 0.
inline ProcessResult RunProcess(const std::vector<std::string>& argv, double timeout = 0,
                                const std::string& log = "/dev/null") {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  ProcessResult r;
  const auto start = Clock::now();
  const pid_t pid = fork();
  if (pid < 0) return r;
  if (pid == 0) {
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      dup2(fd, 1);
      dup2(fd, 2);
    }
    execv(args[0], args.data());  // only async-signal-safe calls after fork
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  while (wait4(pid, &status, WNOHANG, &usage) == 0) {  // poll: ≤ 1 ms of error
    if (timeout > 0 && !r.timed_out && Seconds(start) > timeout) {
      r.timed_out = true;
      kill(pid, SIGKILL);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  r.seconds = Seconds(start);
  r.max_rss_mb = usage.ru_maxrss / 1024.0;  // kB on Linux
  r.cpu_seconds = usage.ru_utime.tv_sec + usage.ru_stime.tv_sec +
                  1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  return r;
}

// `archgeo solve SPEC --quiet --set ...` as a subprocess, writing the report
// (and the mesh if `write_mesh`) to the scratch folder; the report is read back
// into `report` (null if the run failed) and the files are removed (the
// subprocess's output log is kept if it failed). Bad input (exit code 2)
// ends the program with archgeo's message and the same exit code.
inline ProcessResult SolveCommand(const std::string& spec, std::vector<std::string> sets,
                                  Json* report, bool write_mesh = false, double timeout = 0) {
  const fs::path out = Scratch() / ("run_" + std::to_string(getpid()));
  const std::string rep = (out.string() + ".json"), mesh = out.string() + ".ply";
  fs::remove(rep);
  std::vector<std::string> argv = {ARCHGEO_BINARY, "solve", spec, "--quiet"};
  sets.insert(sets.end(), ExtraSets().begin(), ExtraSets().end());
  sets.push_back(write_mesh ? "output={mesh: " + mesh + ", report: " + rep + "}"
                            : "output={report: " + rep + "}");
  for (const std::string& s : sets) argv.insert(argv.end(), {"--set", s});
  const ProcessResult r = RunProcess(argv, timeout, out.string() + ".log");
  if (r.exit_code == 2) {  // bad input: archgeo's message, and the same exit code
    std::cout << std::flush;
    std::cerr << std::ifstream(out.string() + ".log").rdbuf();
    fs::remove(out.string() + ".log");
    std::exit(2);
  }
  *report = nullptr;
  if (r.exit_code == 0 && fs::exists(rep)) *report = Json::parse(std::ifstream(rep));
  for (const std::string& f : {rep, mesh}) fs::remove(f);
  if (r.exit_code == 0) fs::remove(out.string() + ".log");  // kept for a failed run
  return r;
}

// printf into a std::string.
template <typename... Args>
std::string Fmt(const char* format, Args... args) {
  char buf[256];
  std::snprintf(buf, sizeof buf, format, args...);
  return buf;
}

// A number from the report at a JSON pointer ("/after/pq_normalized_max"), NaN if absent.
inline double Get(const Json& j, const char* pointer) {
  const Json::json_pointer p(pointer);
  return j.contains(p) && j.at(p).is_number() ? j.at(p).get<double>() : std::nan("");
}

inline std::string Met(const Json& report) {
  if (report.is_null()) return "-";
  if (!report.contains("tolerances")) return "NO";
  for (const auto& [key, t] : report["tolerances"].items()) {
    if (!t.value("met", false)) return "NO";
  }
  return "yes";
}

// A text table: add rows of cells, print with columns padded to the widest
// cell (width counted in UTF-8 code points, so δ and ∂ line up).
class Table {
 public:
  explicit Table(std::vector<std::string> header) { rows_.push_back(std::move(header)); }
  void Add(std::vector<std::string> row) { rows_.push_back(std::move(row)); }
  void Print(std::ostream& os = std::cout) const {
    std::vector<size_t> width;
    for (const auto& row : rows_) {
      width.resize(std::max(width.size(), row.size()));
      for (size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], Width(row[c]));
    }
    for (size_t i = 0; i < rows_.size(); ++i) {
      std::string line;
      for (size_t c = 0; c < rows_[i].size(); ++c) {
        line += rows_[i][c] + std::string(width[c] - Width(rows_[i][c]) + 2, ' ');
      }
      os << line.substr(0, line.find_last_not_of(' ') + 1) << "\n";
      if (i == 0) {
        size_t total = 0;
        for (size_t w : width) total += w + 2;
        os << std::string(total - 2, '-') << "\n";
      }
    }
  }

 private:
  static size_t Width(const std::string& s) {
    size_t n = 0;
    for (unsigned char ch : s) n += (ch & 0xC0) != 0x80;
    return n;
  }
  std::vector<std::vector<std::string>> rows_;
};

}  // namespace bench
