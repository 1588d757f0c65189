// `hairpipe brdf`: CSV round trips (with and without header, unnormalised vectors), row order, values
// against the exact S within each mode's tolerance, and every bad input: exit 1, a message naming the
// file, line and problem, and no output file (an existing one is left untouched).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

#include "engine/core/shading/fibre_model.h"
#include "tests/hair/hair_test_util.h"
#include "tests/shading/random_directions.h"
#include "tests/support/cli_runner.h"

using hp::test::runCli;
using hp::test::slurp;
using hp::test::TempDir;
using hp::test::writeText;

namespace {
struct Row {
  glm::dvec3 L, V, T;
};

// Random rows with random lengths (0.1 .. 10) per vector, written with 17 significant digits.
std::vector<Row> randomRows(int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> len(0.1, 10.0);
  std::vector<Row> rows;
  for (int i = 0; i < n; ++i) {
    auto t = hp::test::uniformTriple(rng);
    rows.push_back({t.L * len(rng), t.V * len(rng), t.T * len(rng)});
  }
  return rows;
}

std::string csv(const std::vector<Row>& rows, bool header) {
  std::ostringstream os;
  os.precision(17);
  if (header) os << "lx,ly,lz,vx,vy,vz,tx,ty,tz\n";
  for (const Row& r : rows)
    os << r.L.x << "," << r.L.y << "," << r.L.z << "," << r.V.x << "," << r.V.y << "," << r.V.z << "," << r.T.x << ","
       << r.T.y << "," << r.T.z << "\n";
  return os.str();
}

std::vector<glm::dvec3> readS(const std::filesystem::path& p) {
  std::vector<glm::dvec3> s;
  std::istringstream in(slurp(p));
  std::string line;
  while (std::getline(in, line)) {
    glm::dvec3 v;
    char c1 = 0, c2 = 0;
    std::istringstream ls(line);
    ls >> v.x >> c1 >> v.y >> c2 >> v.z;
    EXPECT_TRUE(ls && c1 == ',' && c2 == ',') << "bad output line: " << line;
    s.push_back(v);
  }
  return s;
}

// Fraction of values with e = |S - S_exact| / (|S_exact| + 0.01) <= tol.
double fractionWithin(const std::vector<glm::dvec3>& s, const std::vector<Row>& rows, double tol,
                      hp::FibreModel model = hp::FibreModel::Marschner) {
  int ok = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    glm::dvec3 exact = hp::exactS(model, rows[i].L, rows[i].V, rows[i].T, hp::HairMaterial{});
    for (int c = 0; c < 3; ++c) ok += std::abs(s[i][c] - exact[c]) / (std::abs(exact[c]) + 0.01) <= tol;
  }
  return double(ok) / double(3 * rows.size());
}

TEST(CliBrdf, DirectModeMatchesTheExactSRowByRowWithAHeader) {
  TempDir dir;
  const auto rows = randomRows(200, 1);
  writeText(dir / "dirs.csv", csv(rows, true));
  auto r = runCli({"brdf", "--in", (dir / "dirs.csv").string(), "--out", (dir / "s.csv").string(), "--mode", "direct"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("wrote S for 200 rows (direct"), std::string::npos) << r.out;
  auto s = readS(dir / "s.csv");
  ASSERT_EQ(s.size(), rows.size());
  EXPECT_EQ(fractionWithin(s, rows, 1e-3), 1.0);
}

TEST(CliBrdf, HeaderIsOptionalAndRowOrderIsKept) {
  TempDir dir;
  auto rows = randomRows(50, 2);
  writeText(dir / "with.csv", csv(rows, true));
  std::string blankLines = "\n";  // blank lines are skipped
  blankLines.append(csv(rows, false)).append("\n \n");
  writeText(dir / "without.csv", blankLines);
  std::reverse(rows.begin(), rows.end());
  writeText(dir / "reversed.csv", csv(rows, false));
  for (const char* name : {"with", "without", "reversed"}) {
    auto r = runCli({"brdf", "--in", (dir / (std::string(name) + ".csv")).string(), "--out",
                     (dir / (std::string(name) + ".out")).string(), "--mode", "paper"});
    ASSERT_EQ(r.exitCode, 0) << name << ": " << r.err;
  }
  EXPECT_EQ(slurp(dir / "with.out"), slurp(dir / "without.out"));
  auto forward = readS(dir / "with.out"), backward = readS(dir / "reversed.out");
  ASSERT_EQ(forward.size(), 50u);
  ASSERT_EQ(backward.size(), 50u);
  for (std::size_t i = 0; i < 50; ++i) EXPECT_EQ(forward[i], backward[49 - i]) << "row " << i;
}

// Float and physical modes: the tolerances of the 100k-sample device measurement, applied to 300 rows
// (p99 <= 2%, median <= 0.3%: at least 99% of values within 2% and half within 0.3%). Paper: loose.
// physical is the default mode.
TEST(CliBrdf, LutModesMatchTheExactSWithinTheirTolerance) {
  TempDir dir;
  const auto rows = randomRows(300, 3);
  writeText(dir / "dirs.csv", csv(rows, false));
  auto r = runCli({"brdf", "--in", (dir / "dirs.csv").string(), "--out", (dir / "physical.csv").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto p = readS(dir / "physical.csv");
  ASSERT_EQ(p.size(), rows.size());
  EXPECT_GE(fractionWithin(p, rows, 0.02, hp::FibreModel::Physical), 0.99);
  EXPECT_GE(fractionWithin(p, rows, 0.003, hp::FibreModel::Physical), 0.5);
  r = runCli({"brdf", "--in", (dir / "dirs.csv").string(), "--out", (dir / "float.csv").string(), "--mode", "float"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto s = readS(dir / "float.csv");
  ASSERT_EQ(s.size(), rows.size());
  EXPECT_GE(fractionWithin(s, rows, 0.02), 0.99);
  EXPECT_GE(fractionWithin(s, rows, 0.003), 0.5);
  r = runCli({"brdf", "--in", (dir / "dirs.csv").string(), "--out", (dir / "paper.csv").string(), "--mode", "paper"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  s = readS(dir / "paper.csv");
  ASSERT_EQ(s.size(), rows.size());
  EXPECT_GE(fractionWithin(s, rows, 0.05), 0.5);
}

TEST(CliBrdf, MaterialOptionsChangeTheResult) {
  TempDir dir;
  writeText(dir / "dirs.csv", "0.2,0.9,0.1,-0.3,-0.8,0.2,0,0.1,1\n");
  auto a = runCli({"brdf", "--in", (dir / "dirs.csv").string(), "--out", (dir / "a.csv").string(), "--mode", "direct"});
  auto b = runCli({"brdf", "--in", (dir / "dirs.csv").string(), "--out", (dir / "b.csv").string(), "--mode", "direct",
                   "--absorption", "0.06,0.1,0.2"});
  ASSERT_EQ(a.exitCode, 0) << a.err;
  ASSERT_EQ(b.exitCode, 0) << b.err;
  auto sa = readS(dir / "a.csv"), sb = readS(dir / "b.csv");
  hp::HairMaterial blonde;
  blonde.absorption = {0.06, 0.1, 0.2};
  glm::dvec3 exact = hp::marschnerS({0.2, 0.9, 0.1}, {-0.3, -0.8, 0.2}, {0, 0.1, 1}, blonde);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(sb[0][c], exact[c], 1e-3 * (exact[c] + 0.01));
  EXPECT_GT(sb[0].b, 2.0 * sa[0].b);
}

struct BadInput {
  const char* name;
  std::string content;          // written to NAME.csv unless `missing`
  std::vector<std::string> expected;  // substrings of the message
  bool missing = false;
};

TEST(CliBrdf, BadInputsExitOneNameTheProblemAndWriteNothing) {
  const std::string good = "1,0,0,0,1,0,0,0,1\n";
  const std::vector<BadInput> cases = {
      {"columns", "lx,ly,lz,vx,vy,vz,tx,ty,tz\n" + good + "1,0,0,0,1,0,0,0\n", {":3:", "expected 9", "got 8"}},
      {"extra_column", good + good + "1,0,0,0,1,0,0,0,1,4\n", {":3:", "got 10"}},
      {"text", good + "1,0,zero,0,1,0,0,0,1\n", {":2:", "column 3", "'zero'", "not a number"}},
      {"half_number", "1,0,0,0,1,0,0,0,1x\n", {":1:", "column 9", "not a number"}},
      {"empty_field", "1,0,,0,1,0,0,0,1\n", {":1:", "column 3", "not a number"}},
      {"nan", good + good + "1,0,0,nan,1,0,0,0,1\n", {":3:", "column 4", "not finite"}},
      {"inf", "1,0,0,0,1,0,0,0,-inf\n", {":1:", "column 9", "not finite"}},
      {"overflow", "1e999,0,0,0,1,0,0,0,1\n", {":1:", "column 1", "out of range"}},
      {"zero_L", "0,0,0,0,1,0,0,0,1\n", {":1:", "L is a zero-length vector"}},
      {"zero_V", good + "1,0,0,0,0.0,-0,0,0,1\n", {":2:", "V is a zero-length vector"}},
      {"zero_T", "1,0,0,0,1,0,0,0,0\n", {":1:", "T is a zero-length vector"}},
      {"empty", "", {"no data rows"}},
      {"blank", "\n  \n", {"no data rows"}},
      {"header_only", "lx,ly,lz,vx,vy,vz,tx,ty,tz\n", {"no data rows"}},
      {"missing", "", {"no such input file"}, true},
  };
  TempDir dir;
  for (const BadInput& c : cases) {
    const auto in = dir / (std::string(c.name) + ".csv");
    const auto out = dir / (std::string(c.name) + ".out");
    if (!c.missing) writeText(in, c.content);
    auto r = runCli({"brdf", "--in", in.string(), "--out", out.string(), "--mode", "direct"});
    EXPECT_EQ(r.exitCode, 1) << c.name << ": " << r.err;
    EXPECT_NE(r.err.find(in.string()), std::string::npos) << c.name << ": " << r.err;
    for (const std::string& e : c.expected) EXPECT_NE(r.err.find(e), std::string::npos) << c.name << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << c.name;
  }
  // Only the inputs are left: no temporary files either.
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.path())) ++files;
  EXPECT_EQ(files, cases.size() - 1);
}

TEST(CliBrdf, AFailureLeavesAnExistingOutputUntouched) {
  TempDir dir;
  writeText(dir / "bad.csv", "1,0,0,0,1,0,0,0,1\n1,2,3\n");
  writeText(dir / "s.csv", "previous\n");
  auto r = runCli({"brdf", "--in", (dir / "bad.csv").string(), "--out", (dir / "s.csv").string()});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(slurp(dir / "s.csv"), "previous\n");
}

TEST(CliBrdf, BadOptionsExitOne) {
  TempDir dir;
  writeText(dir / "dirs.csv", "1,0,0,0,1,0,0,0,1\n");
  const std::string in = (dir / "dirs.csv").string(), out = (dir / "s.csv").string();
  auto mode = runCli({"brdf", "--in", in, "--out", out, "--mode", "bogus"});
  EXPECT_EQ(mode.exitCode, 1);
  EXPECT_NE(mode.err.find("--mode bogus"), std::string::npos) << mode.err;
  auto eta = runCli({"brdf", "--in", in, "--out", out, "--eta", "0.5"});
  EXPECT_EQ(eta.exitCode, 1);
  EXPECT_NE(eta.err.find("--eta"), std::string::npos) << eta.err;
  auto device = runCli({"brdf", "--in", in, "--out", out, "--device", "nosuchdevice"});
  EXPECT_EQ(device.exitCode, 1);
  EXPECT_NE(device.err.find("nosuchdevice"), std::string::npos) << device.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}
}  // namespace
