// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// End to end through the `archgeo` binary: planarising a generated grid,
// invariance under similarity, and every class of bad input (exit 2, a
// message naming the file, no output, the input untouched).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "io/io.h"
#include "tests/scratch_dir.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

namespace fs = std::filesystem;

struct Outcome {
  int code;
  std::string output;  // stdout + stderr
};

Outcome Archgeo(const std::string& args, const std::string& env = "") {
  const std::string cmd = env + ARCHGEO_BINARY + " " + args + " 2>&1";
  Outcome o{0, ""};
  FILE* pipe = popen(cmd.c_str(), "r");
  std::array<char, 4096> buf;
  while (size_t n = fread(buf.data(), 1, buf.size(), pipe)) o.output.append(buf.data(), n);
  const int status = pclose(pipe);
  o.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return o;
}

std::string Slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

class CliTest : public ScratchDirTest {
 protected:
  std::string Spec(const std::string& mesh, const std::string& extra = "") const {
    return WriteFile("spec.yaml", "mesh: " + mesh +
                                      "\noutput:\n  mesh: out.ply\n  report: out.json\n" + extra);
  }
  // Asserts the bad-input contract for `args`: exit 2, the message names
  // `needle`, no output files, and every file in `inputs` unchanged.
  void ExpectBadInput(const std::string& args, const std::string& needle,
                      const std::vector<std::string>& inputs) const {
    std::vector<std::string> before;
    for (const auto& f : inputs) before.push_back(Slurp(f));
    const Outcome o = Archgeo(args);
    EXPECT_EQ(o.code, 2) << o.output;
    EXPECT_NE(o.output.find(needle), std::string::npos) << "missing '" << needle << "' in\n"
                                                        << o.output;
    EXPECT_FALSE(fs::exists(Path("out.ply")));
    EXPECT_FALSE(fs::exists(Path("out.json")));
    for (const auto& entry : fs::directory_iterator(dir_)) {
      EXPECT_EQ(entry.path().string().find(".tmp-"), std::string::npos) << entry.path();
    }
    for (size_t i = 0; i < inputs.size(); ++i) EXPECT_EQ(Slurp(inputs[i]), before[i]);
  }

};

TEST_F(CliTest, PlanarisesAGeneratedNonPlanarGrid) {
  ASSERT_EQ(Archgeo("generate " + Path("grid.obj") + " --nu 16 --nv 12 --noise 0.03").code, 0);
  const std::string spec = Spec("grid.obj");
  const Outcome o = Archgeo("solve " + spec + " --quiet");
  ASSERT_EQ(o.code, 0) << o.output;
  const auto report = nlohmann::json::parse(Slurp(Path("out.json")));
  EXPECT_GT(report["before"]["pq_normalized_max"].get<double>(), 1e-2);
  EXPECT_LE(report["after"]["pq_normalized_max"].get<double>(), 1e-3);
  EXPECT_TRUE(report["tolerances"]["tolerance.pq_normalized_max"]["met"].get<bool>());
  EXPECT_LT(report["after"]["displacement_max_relative"].get<double>(), 0.02);
  // Within a tenth of a panel of the input surface (mean edge ≈ 0.05 of the
  // diagonal of a 16 × 12 grid): the noise alone is up to 0.03 panels, and a
  // planar-quad net of the curved roof cannot follow it exactly either.
  EXPECT_LT(report["after"]["surface_distance_max_relative"].get<double>(), 0.005);
  const Mesh in = ReadMesh(Path("grid.obj"));
  const Mesh out = ReadMesh(Path("out.ply"));
  EXPECT_EQ(out.number_of_vertices(), in.number_of_vertices());
  EXPECT_EQ(out.number_of_faces(), in.number_of_faces());

  // `measure` on the output gives the report's numbers.
  const Outcome m = Archgeo("measure " + Path("out.ply") + " --reference " + Path("grid.obj") +
                        " --json");
  ASSERT_EQ(m.code, 0) << m.output;
  const auto measured = nlohmann::json::parse(m.output);
  EXPECT_NEAR(measured["metrics"]["pq_normalized_max"].get<double>(),
              report["after"]["pq_normalized_max"].get<double>(), 1e-12);
  EXPECT_NEAR(measured["metrics"]["displacement_max"].get<double>(),
              report["after"]["displacement_max"].get<double>(), 1e-12);
  // ... and the validity section, against the input ...
  EXPECT_TRUE(measured["validity"]["valid"].get<bool>());
  EXPECT_TRUE(measured["validity"]["against_reference"].get<bool>());
  // ... for any pair: a folded copy of the output against it is not valid; a
  // reference of another topology gives the checks of the mesh alone.
  Mesh folded = out;
  const VertexIndex centre(VertexIndex(out.number_of_vertices() / 2));
  folded.point(centre) = folded.point(centre) + 5 * (folded.point(VertexIndex(0)) - folded.point(centre));
  WriteMesh(Path("folded.ply"), folded);
  const Outcome f = Archgeo("measure " + Path("folded.ply") + " --reference " + Path("out.ply"));
  EXPECT_NE(f.output.find("validity against the reference: NOT valid"), std::string::npos)
      << f.output;
  ASSERT_EQ(Archgeo("generate " + Path("other.obj") + " --nu 5 --nv 4").code, 0);
  const Outcome alone = Archgeo("measure " + Path("out.ply") + " --reference " + Path("other.obj"));
  EXPECT_NE(alone.output.find("validity of the mesh alone (the reference has another topology"),
            std::string::npos)
      << alone.output;
}

// The same problem scaled by 1000 and rotated: same relative metrics, same
// output up to the similarity.
// Unless the user chose an OpenMP wait policy, archgeo runs with the passive
// one (libgomp's idle threads do not spin: GOMP_SPINCOUNT 0); a user's choice
// is kept.
TEST_F(CliTest, OpenMpThreadsWaitPassivelyUnlessTheUserChose) {
  const auto last_spin_count = [](const std::string& out) {
    const size_t at = out.rfind("GOMP_SPINCOUNT = '");
    return at == std::string::npos ? std::string("none") : out.substr(at + 18, out.find('\'', at + 18) - at - 18);
  };
  const Outcome unset = Archgeo("--version", "env -u OMP_WAIT_POLICY OMP_DISPLAY_ENV=verbose ");
  EXPECT_EQ(unset.code, 0);
  EXPECT_EQ(last_spin_count(unset.output), "0") << unset.output;
  const Outcome active = Archgeo("--version", "env OMP_WAIT_POLICY=active OMP_DISPLAY_ENV=verbose ");
  EXPECT_EQ(active.code, 0);
  EXPECT_NE(last_spin_count(active.output), "0") << active.output;
}

// The report names the kernels OpenBLAS ran (blas_kernels): those of
// OPENBLAS_CORETYPE when set, else a non-empty core name.
TEST_F(CliTest, TheReportNamesTheBlasKernels) {
  ASSERT_EQ(Archgeo("generate " + Path("grid.obj") + " --nu 4 --nv 3").code, 0);
  const std::string spec = Spec(Path("grid.obj"), "problem: planar_quads\n");
  const auto kernels = [&](const std::string& env) {
    const Outcome o = Archgeo("solve " + spec + " --quiet", env);
    EXPECT_EQ(o.code, 0) << o.output;
    return nlohmann::json::parse(Slurp(Path("out.json")))["blas_kernels"].get<std::string>();
  };
  EXPECT_FALSE(kernels("env -u OPENBLAS_CORETYPE ").empty());
  EXPECT_EQ(kernels("env OPENBLAS_CORETYPE=Sandybridge "), "Sandybridge");
  EXPECT_EQ(kernels("env OPENBLAS_CORETYPE=Haswell "), "Haswell");
}

// tolerance.energy_not_above_input (planar_quads, on by default): without the
// fairness terms, planarity alone raises E on a gently noisy roof (3.067 ->
// 3.074); that run ends exit 4 with the tolerance named, exit 0 when the key
// is off; the defaults keep E below the input's.
TEST_F(CliTest, PlanarQuadsThatRaiseTheInputsEAreAMissedTolerance) {
  ASSERT_EQ(Archgeo("generate " + Path("r.obj") + " --nu 8 --nv 8 --noise 0.01").code, 0);
  const std::string solve = "solve " + std::string(ARCHGEO_SOURCE_DIR) +
                            "/examples/planar_quads.yaml --set mesh=" + Path("r.obj") +
                            " --set output.mesh= --set output.image= --set output.report=" +
                            Path("out.json");
  const std::string unfair = " --set terms.fairness.weight=0 --set terms.dihedral_energy.weight=0";
  const auto entry = [&] {
    return nlohmann::json::parse(Slurp(Path("out.json")))["tolerances"]
                                ["tolerance.energy_not_above_input"];
  };
  const Outcome raised = Archgeo(solve + unfair);
  EXPECT_EQ(raised.code, 4) << raised.output;
  EXPECT_NE(raised.output.find("tolerance.energy_not_above_input: E"), std::string::npos);
  EXPECT_NE(raised.output.find("NOT met"), std::string::npos);
  EXPECT_FALSE(entry()["met"].get<bool>());
  const Outcome off = Archgeo(solve + unfair + " --set tolerance.energy_not_above_input=false");
  EXPECT_EQ(off.code, 0) << off.output;
  const Outcome defaults = Archgeo(solve);
  EXPECT_EQ(defaults.code, 0) << defaults.output;
  EXPECT_TRUE(entry()["met"].get<bool>());
  EXPECT_GT(entry()["bound"].get<double>(), 0);
}

TEST_F(CliTest, SimilarInputGivesSimilarOutput) {
  ASSERT_EQ(Archgeo("generate " + Path("a.obj") + " --nu 14 --nv 10 --noise 0.03").code, 0);
  Mesh mesh = ReadMesh(Path("a.obj"));
  const double s = 1000, c = std::cos(0.7), sn = std::sin(0.7);
  auto similar = [&](const Point& p) {
    return Point(s * (c * p.x() - sn * p.z()) + 5, s * p.y() - 3, s * (sn * p.x() + c * p.z()));
  };
  for (VertexIndex v : mesh.vertices()) mesh.point(v) = similar(mesh.point(v));
  WriteMesh(Path("b.obj"), mesh);

  ASSERT_EQ(Archgeo("solve " + Spec("a.obj") + " --quiet").code, 0);
  fs::rename(Path("out.json"), Path("a.json"));
  fs::rename(Path("out.ply"), Path("a.ply"));
  ASSERT_EQ(Archgeo("solve " + Spec("b.obj") + " --quiet").code, 0);
  const auto ra = nlohmann::json::parse(Slurp(Path("a.json")));
  const auto rb = nlohmann::json::parse(Slurp(Path("out.json")));
  for (const char* key : {"pq_normalized_max", "pq_normalized_mean", "warp_max",
                          "displacement_max_relative", "surface_distance_max_relative",
                          "prox_max_relative"}) {
    const double a = ra["after"][key].get<double>(), b = rb["after"][key].get<double>();
    EXPECT_NEAR(a, b, 1e-4 * std::abs(a)) << key;
  }
  const Mesh oa = ReadMesh(Path("a.ply"));
  const Mesh ob = ReadMesh(Path("out.ply"));
  double worst = 0;
  for (VertexIndex v : oa.vertices()) {
    worst = std::max(worst, std::sqrt(CGAL::squared_distance(similar(oa.point(v)), ob.point(v))));
  }
  EXPECT_LT(worst / s, 1e-6);
}

TEST_F(CliTest, SetOverridesMeshAndOutputs) {
  ASSERT_EQ(Archgeo("generate " + Path("g.obj") + " --nu 6 --nv 5").code, 0);
  const std::string spec = WriteFile("s.yaml", "mesh: missing.obj\n");
  const Outcome o = Archgeo("solve " + spec + " --quiet --set mesh=" + Path("g.obj") +
                        " --set output.mesh=" + Path("o.obj") + " --set solver.num_threads=1");
  EXPECT_EQ(o.code, 0) << o.output;
  EXPECT_TRUE(fs::exists(Path("o.obj")));
}

TEST_F(CliTest, BadInputMissingMesh) {
  const std::string spec = Spec("nowhere.obj");
  ExpectBadInput("solve " + spec, "nowhere.obj", {spec});
}

TEST_F(CliTest, BadInputMissingSpec) { ExpectBadInput("solve " + Path("no.yaml"), "no.yaml", {}); }

TEST_F(CliTest, BadInputMalformedYaml) {
  const std::string spec = WriteFile("spec.yaml", "mesh: a.obj\nsolver: {num_threads: 1\n");
  ExpectBadInput("solve " + spec, "spec.yaml:", {spec});
}

TEST_F(CliTest, BadInputUnknownKey) {
  ASSERT_EQ(Archgeo("generate " + Path("g.obj") + " --nu 4 --nv 4").code, 0);
  const std::string spec = Spec("g.obj", "solver:\n  treads: 1\n");
  ExpectBadInput("solve " + spec, "spec.yaml:6: key 'solver.treads'", {spec, Path("g.obj")});
}

TEST_F(CliTest, BadInputWrongType) {
  ASSERT_EQ(Archgeo("generate " + Path("g.obj") + " --nu 4 --nv 4").code, 0);
  const std::string spec = Spec("g.obj", "terms: {anchor: heavy}\n");
  ExpectBadInput("solve " + spec, "key 'terms.anchor'", {spec, Path("g.obj")});
  ExpectBadInput("solve " + spec + " --set terms.anchor=[1]", "--set", {spec});
}

TEST_F(CliTest, BadInputNanCoordinates) {
  const std::string mesh = WriteFile("nan.obj", "v 0 0 0\nv 1 0 0\nv 1 1 nan\nv 0 1 0\nf 1 2 3 4\n");
  const std::string spec = Spec("nan.obj");
  ExpectBadInput("solve " + spec, "nan.obj", {spec, mesh});
}

TEST_F(CliTest, BadInputEmptyMesh) {
  const std::string mesh = WriteFile("empty.off", "OFF\n0 0 0\n");
  const std::string spec = Spec("empty.off");
  ExpectBadInput("solve " + spec, "empty.off", {spec, mesh});
}

TEST_F(CliTest, BadInputNonManifold) {
  // Three quads sharing one edge.
  const std::string mesh = WriteFile(
      "nm.obj",
      "v 0 0 0\nv 0 1 0\nv 1 0 0\nv 1 1 0\nv -1 0 0\nv -1 1 0\nv 0 0 1\nv 0 1 1\n"
      "f 1 3 4 2\nf 2 6 5 1\nf 1 7 8 2\n");
  const std::string spec = Spec("nm.obj");
  ExpectBadInput("solve " + spec, "nm.obj", {spec, mesh});
}

TEST_F(CliTest, BadInputDegenerateFace) {
  const std::string mesh =
      WriteFile("deg.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nf 1 2 3 4\n");
  const std::string spec = Spec("deg.obj");
  ExpectBadInput("solve " + spec, "deg.obj", {spec, mesh});
}

TEST_F(CliTest, BadInputTrianglesWhereQuadsAreNeeded) {
  const std::string mesh = WriteFile("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0.2\nf 1 2 3\nf 2 4 3\n");
  const std::string spec = Spec("tri.obj");
  ExpectBadInput("solve " + spec, "only triangles", {spec, mesh});
}

TEST_F(CliTest, BadInputFixedVertexOutOfRange) {
  ASSERT_EQ(Archgeo("generate " + Path("g.obj") + " --nu 4 --nv 4").code, 0);
  const std::string spec = Spec("g.obj", "fixed: [0, 999]\n");
  ExpectBadInput("solve " + spec, "spec.yaml:5: key 'fixed'", {spec, Path("g.obj")});
}

TEST_F(CliTest, OutputNeverOverwritesTheInput) {
  ASSERT_EQ(Archgeo("generate " + Path("g.obj") + " --nu 4 --nv 4").code, 0);
  const std::string spec = WriteFile("spec.yaml", "mesh: g.obj\noutput: {mesh: g.obj}\n");
  ExpectBadInput("solve " + spec, "g.obj", {spec, Path("g.obj")});
}

TEST_F(CliTest, BadOutputNamesFailBeforeAnyWork) {
  ASSERT_EQ(Archgeo("generate " + Path("g.obj") + " --nu 4 --nv 4").code, 0);
  const std::string spec = WriteFile("spec.yaml", "mesh: g.obj\noutput: {mesh: out.stl}\n");
  const Outcome o = Archgeo("solve " + spec);
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.output.find("out.stl"), std::string::npos) << o.output;
  EXPECT_EQ(o.output.find("iter"), std::string::npos) << "solved before failing:\n" << o.output;
  const std::string over = WriteFile("over.yaml", "mesh: g.obj\noutput: {report: g.obj}\n");
  const Outcome p = Archgeo("solve " + over);
  EXPECT_EQ(p.code, 2);
  EXPECT_EQ(p.output.find("iter"), std::string::npos) << "solved before failing:\n" << p.output;
}

TEST_F(CliTest, BadCommandLine) {
  EXPECT_EQ(Archgeo("frobnicate").code, 2);
  EXPECT_EQ(Archgeo("solve").code, 2);
  EXPECT_EQ(Archgeo("measure " + Path("none.off")).code, 2);
  EXPECT_EQ(Archgeo("solve --help").code, 0);
}

// A mistyped command gets the nearest command (within two edits); `archgeo
// help` lists every command; `spec --help` every problem, custom included.
TEST_F(CliTest, HelpListsTheCommandsAndAMistypeGetsASuggestion) {
  const Outcome typo = Archgeo("slove " + Path("spec.yaml"));
  EXPECT_EQ(typo.code, 2);
  EXPECT_NE(typo.output.find("'slove' is not a command; did you mean 'solve'?"), std::string::npos)
      << typo.output;
  const Outcome far = Archgeo("frobnicate");
  EXPECT_EQ(far.output.find("did you mean"), std::string::npos) << far.output;
  EXPECT_NE(Archgeo("help mesure").output.find("did you mean 'measure'?"), std::string::npos);
  const Outcome help = Archgeo("help");
  EXPECT_EQ(help.code, 0);
  for (const char* command :
       {"solve", "spec", "terms", "measure", "generate", "darboux", "render", "bench"}) {
    EXPECT_NE(help.output.find(std::string("\n  ") + command + " "), std::string::npos)
        << command << " missing in\n" << help.output;
  }
  // The problems the registry has, as `spec` names them for an unknown one.
  const std::string unknown = Archgeo("spec nosuch").output;
  const size_t open = unknown.find("is not a problem ("), close = unknown.find(')', open);
  ASSERT_NE(close, std::string::npos) << unknown;
  std::stringstream names(unknown.substr(open + 18, close - open - 18));
  const Outcome spec = Archgeo("spec --help");
  int listed = 0;
  for (std::string name; std::getline(names, name, ',');) {
    name.erase(0, name.find_first_not_of(' '));
    EXPECT_NE(spec.output.find(name), std::string::npos) << name << " missing in\n" << spec.output;
    ++listed;
  }
  EXPECT_GE(listed, 10);  // custom included
  EXPECT_NE(unknown.find("custom"), std::string::npos) << unknown;
  EXPECT_EQ(Archgeo("spec custom").code, 0);
}

}  // namespace
}  // namespace archgeo

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

// `archgeo measure` recognises the hyperbolic paraboloid sampled on its
// rulings as an exact A-net whose H-net is the surface itself [Shi 2014].
TEST_F(CliTest, MeasureRecognisesTheHyperbolicParaboloidAsAnHNet) {
  ASSERT_EQ(Archgeo("generate " + Path("hp.obj") + " --surface hyperbolic_paraboloid").code, 0);
  const Outcome o = Archgeo("measure " + Path("hp.obj") + " --json");
  ASSERT_EQ(o.code, 0) << o.output;
  const nlohmann::json m = nlohmann::json::parse(o.output)["metrics"];
  EXPECT_LE(m["star_planarity_max"].get<double>(), 1e-12);
  EXPECT_LE(m["alpha_max"].get<double>(), 1e-6);
  EXPECT_NEAR(m["W_min"].get<double>(), 1.0, 1e-12);
  EXPECT_NEAR(m["W_max"].get<double>(), 1.0, 1e-12);
  EXPECT_EQ(m["odd_valence_vertices"].get<double>(), 0);
  // Pellis' analysis is printed for any mesh.
  EXPECT_GT(m["E"].get<double>(), 0);
  EXPECT_GE(m["E_prime"].get<double>(), m["E"].get<double>());
}

// `archgeo measure` prints the rows that describe the mesh: the A-net and
// H-net rows for the A-net, not for a plain roof of near-planar quads (its
// star planarity is far from 0), nor its saddle rows (defined on triangle
// stars); `--all` prints them too, and the JSON has every metric.
TEST_F(CliTest, MeasurePrintsTheMetricsThatApplyAndAllWithAll) {
  ASSERT_EQ(Archgeo("generate " + Path("hp.obj") + " --surface hyperbolic_paraboloid").code, 0);
  ASSERT_EQ(Archgeo("generate " + Path("roof.obj") + " --noise 0.2").code, 0);
  const Outcome anet = Archgeo("measure " + Path("hp.obj"));
  EXPECT_NE(anet.output.find("A-net star planarity max"), std::string::npos) << anet.output;
  EXPECT_NE(anet.output.find("H-net kink"), std::string::npos) << anet.output;
  const Outcome roof = Archgeo("measure " + Path("roof.obj"));
  ASSERT_EQ(roof.code, 0) << roof.output;
  for (const char* row : {"A-net star planarity", "H-net kink", "conical residual", "bad saddles",
                          "non-convex quads"}) {
    EXPECT_EQ(roof.output.find(row), std::string::npos) << row << " in\n" << roof.output;
  }
  EXPECT_NE(roof.output.find("δ_PQ,n max"), std::string::npos) << roof.output;
  EXPECT_NE(roof.output.find("E = Σ ℓ ℓ*"), std::string::npos) << roof.output;
  const Outcome all = Archgeo("measure " + Path("roof.obj") + " --all");
  EXPECT_NE(all.output.find("A-net star planarity"), std::string::npos) << all.output;
  EXPECT_NE(all.output.find("bad saddles"), std::string::npos) << all.output;
  const Outcome json = Archgeo("measure " + Path("roof.obj") + " --json");
  EXPECT_TRUE(nlohmann::json::parse(json.output)["metrics"].contains("star_planarity_max"));
}

// `archgeo darboux` (Shi 2014, eq. 12; the map itself is checked in
// test_hnet_geometry): writes a PLY patchwork with normals, isophote colours
// and rulings, and refuses c = 1, a non-PLY output and a singular projective
// map without writing anything.
// A complex that is not a valid quad complex is written for inspection but
// misses the command's goal: exit 4 and a WARNING line, not exit 0.
TEST_F(CliTest, SpectralComplexThatIsNotAValidQuadComplexExits4) {
  ASSERT_EQ(Archgeo("generate " + Path("torus.obj") + " --surface torus --nu 24 --nv 12").code, 0);
  const Outcome bad = Archgeo("spectral " + Path("torus.obj") + " --complex " + Path("c1.obj") +
                              " --eigenfunction 33");
  EXPECT_EQ(bad.code, 4) << bad.output;
  EXPECT_NE(bad.output.find("valid no"), std::string::npos) << bad.output;
  EXPECT_NE(bad.output.find("WARNING: the goal was missed (exit 4): the complex of eigenfunction 33 "
                            "is not a valid quad complex"),
            std::string::npos)
      << bad.output;
  EXPECT_TRUE(fs::exists(Path("c1.obj")));
  const Outcome good = Archgeo("spectral " + Path("torus.obj") + " --complex " + Path("c.obj") +
                               " --eigenfunction 10");
  EXPECT_EQ(good.code, 0) << good.output;
  EXPECT_NE(good.output.find("valid yes"), std::string::npos) << good.output;
  EXPECT_EQ(good.output.find("WARNING"), std::string::npos) << good.output;
}

// examples/wave_torus.yaml end to end (Fig. 14, 12,000 vertices): one
// integrated start, the regular complex, exit 0.
TEST_F(CliTest, WaveTorusExampleGivesTheRegularComplex) {
  const Outcome o = Archgeo("solve " + std::string(ARCHGEO_SOURCE_DIR) +
                            "/examples/wave_torus.yaml --quiet --set output.mesh=" + Path("t.ply") +
                            " --set output.complex=" + Path("c.obj") + " --set output.quasi_dual=" +
                            Path("q.obj") + " --set output.report=" + Path("t.json"));
  ASSERT_EQ(o.code, 0) << o.output;
  const auto w = nlohmann::json::parse(Slurp(Path("t.json"))).at("details").at("wave");
  EXPECT_TRUE(w.at("valid").get<bool>());
  EXPECT_EQ(w.at("valid_starts").get<int>(), 1);
  EXPECT_EQ(w.at("maxima").get<int>(), 144);
  EXPECT_EQ(w.at("saddles").get<int>(), 288);
  EXPECT_EQ(w.at("quasi_dual").at("quads").get<int>(), 288);
  EXPECT_EQ(w.at("quasi_dual").at("irregular_vertices").get<int>(), 0);
}

// examples/wave_quads.yaml end to end on the inspired mesh with two of its
// ten starts (the ten: benchmarks/wave): both give a valid complex, the one
// of lower E is kept, the boundary holds, and the quad mesh is written.
TEST_F(CliTest, WaveQuadsExampleKeepsTheBestValidStart) {
  const Outcome o = Archgeo("solve " + std::string(ARCHGEO_SOURCE_DIR) +
                            "/examples/wave_quads.yaml --quiet --set wave.restarts=2"
                            " --set output.mesh=" + Path("w.ply") + " --set output.complex=" +
                            Path("c.obj") + " --set output.quasi_dual=" + Path("q.obj") +
                            " --set output.quads=" + Path("m.obj") +
                            " --set output.report=" + Path("w.json"));
  ASSERT_EQ(o.code, 0) << o.output;
  const auto report = nlohmann::json::parse(Slurp(Path("w.json")));
  const auto& w = report.at("details").at("wave");
  const auto& charts = report.at("details").at("charts");
  EXPECT_GT(charts.at("output_quads").get<int>(), 0);
  EXPECT_EQ(ReadMesh(Path("m.obj")).number_of_faces(),
            size_t(charts.at("output_quads").get<int>() + charts.at("output_triangles").get<int>()));
  EXPECT_TRUE(w.at("valid").get<bool>());
  EXPECT_EQ(w.at("restarts").get<int>(), 2);
  EXPECT_EQ(w.at("valid_starts").get<int>(), 2);
  std::vector<double> energies;  // of the starts' rounds (after the input and the curl correction)
  for (const auto& round : report.at("rounds")) {
    if (round.at("stage") != "restart") continue;
    energies.push_back(round.at("measures").at("wave_energy").get<double>());
  }
  ASSERT_EQ(energies.size(), 2u);
  const int lower = energies[0] <= energies[1] ? 1 : 2;
  EXPECT_EQ(w.at("kept_start").get<int>(), lower);
  EXPECT_LE(w.at("feature_sin_max").get<double>(), 1e-6);
  EXPECT_GT(w.at("quasi_dual").at("quads").get<int>(), 0);
}

TEST_F(CliTest, DarbouxWritesAPatchworkAndRefusesBadInput) {
  ASSERT_EQ(Archgeo("generate " + Path("hp.obj") + " --surface hyperbolic_paraboloid").code, 0);
  const Outcome o = Archgeo("darboux " + Path("hp.obj") + " " + Path("d.ply") +
                            " --c -1 --samples 4 --isophotes 10 --rulings " + Path("r.obj"));
  ASSERT_EQ(o.code, 0) << o.output;
  const std::string ply = Slurp(Path("d.ply"));
  EXPECT_EQ(ply.rfind("ply\n", 0), 0u);
  EXPECT_NE(ply.find("property float nx"), std::string::npos);
  EXPECT_NE(ply.find("property uchar red"), std::string::npos);
  EXPECT_TRUE(fs::exists(Path("r.obj")));
  ExpectBadInput("darboux " + Path("hp.obj") + " " + Path("out.ply") + " --c 1", "c must be",
                 {Path("hp.obj")});
  ExpectBadInput("darboux " + Path("hp.obj") + " " + Path("out.json"), "PLY", {Path("hp.obj")});
  ExpectBadInput("darboux " + Path("hp.obj") + " " + Path("out.ply") +
                     " --projective 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 0",
                 "singular", {Path("hp.obj")});
}

}  // namespace
}  // namespace archgeo
