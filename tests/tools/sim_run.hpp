#pragma once
// The built carrom-sim (CARROM_SIM_PATH) run through the shell for the tools tests: its standard
// output, its standard error (sent to a temp file) and its exit code.

#include "support/command_run.hpp"
#include "support/read_file.hpp"

#include <gtest/gtest.h>

#include <string>

namespace carrom::sim_testing {

struct SimRun {
    int exit_code = -1;
    std::string out;
    std::string err;
};

// Unique per test (suite and name), so that tests run in parallel processes do not share files.
inline std::string temp_path(const std::string& name) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    return ::testing::TempDir() + "carrom_sim_" + info->test_suite_name() + "_" + info->name() +
           "_" + name;
}

// Runs `carrom-sim <args>`; stderr goes to a temp file, read back into err.
inline SimRun run_sim(const std::string& args) {
    const std::string err_path = temp_path("stderr.txt");
    const std::string command = std::string(CARROM_SIM_PATH) + " " + args + " 2>" + err_path;
    const test_support::CommandRun ran = test_support::run_command(command);
    return {ran.exit, ran.out, test_support::read_file(err_path)};
}

} // namespace carrom::sim_testing
