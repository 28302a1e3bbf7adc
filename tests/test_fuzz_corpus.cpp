// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Every input of the committed fuzz corpora (fuzz/corpus/: seeds, coverage
// inputs and the regression inputs of past findings) read the way the
// harnesses read it: success or an InputError, never another exception.
// The libFuzzer runs themselves are tools/fuzz_smoke.sh (CI) and fuzz/README.md.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/input_error.h"
#include "io/io.h"
#include "problems/spec/spec.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

namespace fs = std::filesystem;

std::string Slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

fs::path Corpus(const std::string& name) {
  return fs::path(ARCHGEO_SOURCE_DIR) / "fuzz" / "corpus" / name;
}

TEST(FuzzCorpus, MeshReadersNeverFailInternally) {
  int files = 0;
  for (const std::string format : {"obj", "off", "ply"}) {
    ASSERT_TRUE(fs::is_directory(Corpus(format))) << format;
    for (const auto& entry : fs::directory_iterator(Corpus(format))) {
      ++files;
      try {
        ReadMeshFromMemory("fuzz." + format, Slurp(entry.path()));
      } catch (const InputError&) {
      } catch (const std::exception& e) {
        ADD_FAILURE() << entry.path() << ": " << e.what();
      }
    }
  }
  EXPECT_GT(files, 100);
}

TEST(FuzzCorpus, SpecReaderNeverFailsInternally) {
  int files = 0;
  for (const auto& entry : fs::directory_iterator(Corpus("spec"))) {
    ++files;
    try {
      ParseSpec(Slurp(entry.path()), entry.path().string());
    } catch (const InputError&) {
    } catch (const std::exception& e) {
      ADD_FAILURE() << entry.path() << ": " << e.what();
    }
  }
  EXPECT_GT(files, 10);
}

}  // namespace
}  // namespace archgeo
