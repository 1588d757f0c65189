#pragma once
// Contract: what the `hairpipe bench` suites share. `benchCommand` is the one `bench` subcommand (the
// whole frame, cmd_bench.cpp); each other suite (sim, strands, opacity, instances, head, assets) is a
// subcommand of it, `hairpipe bench SUITE [options]`, added with `benchSuite` whatever the order in which
// the commands register; an option of `bench` itself given before a suite's name is refused.
// `createBenchContext` is the device every suite measures on: headless, no validation (it would distort
// the timings), refused with hp::Error naming the suite when it has no timestamps.
#include <CLI/CLI.hpp>

#include <memory>
#include <string>

#include "engine/vk/context.h"

namespace hp::cli {
CLI::App* benchCommand(CLI::App& app);
CLI::App* benchSuite(CLI::App& app, const std::string& suite, const std::string& description);
std::unique_ptr<vk::Context> createBenchContext(const std::string& device, const std::string& command);
}  // namespace hp::cli
