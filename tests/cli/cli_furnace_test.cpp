// `hairpipe furnace`: the white-furnace integral per channel, one CSV row per outgoing angle.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "tests/support/cli_runner.h"

using hp::test::runCli;

namespace {
// The rows after the "theta_r_deg,r,g,b" header: {theta, r, g, b}.
std::vector<std::vector<double>> rows(const std::string& out) {
  std::vector<std::vector<double>> r;
  std::istringstream in(out.substr(out.find("theta_r_deg,r,g,b")));
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::vector<double> v;
    std::istringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) v.push_back(std::stod(cell));
    r.push_back(v);
  }
  return r;
}
}  // namespace

TEST(CliFurnace, PhysicalConservesEnergyAndThePaperModelDoesNot) {
  auto white = runCli({"furnace", "--absorption", "0,0,0", "--theta-r", "0", "--theta-r", "70"});
  ASSERT_EQ(white.exitCode, 0) << white.err;
  auto w = rows(white.out);
  ASSERT_EQ(w.size(), 2u);
  for (const auto& row : w)
    for (int c = 1; c <= 3; ++c) EXPECT_NEAR(row[c], 1.0, 1e-4) << white.out;
  auto brown = runCli({"furnace"});
  ASSERT_EQ(brown.exitCode, 0) << brown.err;
  auto b = rows(brown.out);
  ASSERT_EQ(b.size(), 9u);  // -80..80 deg
  for (const auto& row : b) {
    EXPECT_LT(row[3], row[1]) << "brown: blue is absorbed most";
    for (int c = 1; c <= 3; ++c) EXPECT_LE(row[c], 1.0);
  }
  auto paper = runCli({"furnace", "--model", "paper", "--absorption", "0,0,0", "--theta-r", "0", "--panels", "24"});
  ASSERT_EQ(paper.exitCode, 0) << paper.err;
  EXPECT_GT(rows(paper.out).at(0).at(2), 1.5) << paper.out;
}

TEST(CliFurnace, BadOptionsExitOne) {
  hp::test::expectRefused({"furnace"}, {{{"--model", "bogus"}, "--model"},
                                        {{"--theta-r", "95"}, "--theta-r"},
                                        {{"--panels", "2"}, "--panels"},
                                        {{"--beta-n", "1"}, "betaN"},
                                        {{"--tilt-variation", "12"}, "tiltVariation"},
                                        {{"--roughness-variation", "-0.1"}, "roughnessVariation"}});
}
