// tests/cli_test.cpp: the `drange` command run as a user runs it (through the shell, with
// files and redirections): outputs, messages, and the documented exit code of each outcome.
#include <algorithm>
#include <cstdio>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "cli_runner.hpp"
#include "drange/generate.hpp"
#include "drange/io.hpp"
#include "temp_dir.hpp"

namespace drange {
namespace {

using testing::CliRun;
using testing::contains;
using testing::count_entries;
using testing::kSquareWithCentre;
using testing::read_text;
using testing::run_cli;
using testing::TempDir;
using testing::write_text;

// ---------------------------------------------------------------- help, version, usage errors

TEST(Cli, Version) {
  TempDir dir;
  const CliRun run = run_cli(dir, {"--version"});
  EXPECT_EQ(run.code, 0);
  EXPECT_EQ(run.out, "drange 0.1.0\n");
}

TEST(Cli, GeneralHelp) {
  TempDir dir;
  for (const std::vector<std::string>& args : {std::vector<std::string>{"--help"}, {"-h"}, {"help"}}) {
    const CliRun run = run_cli(dir, args);
    EXPECT_EQ(run.code, 0) << args[0];
    EXPECT_TRUE(contains(run.out, "Usage: drange COMMAND")) << args[0];
    for (const char* command : {"delaunay", "check", "generate"}) EXPECT_TRUE(contains(run.out, command));
    EXPECT_TRUE(contains(run.out, "Exit codes:"));
    EXPECT_TRUE(contains(run.out, "  4   degenerate input"));
  }
}

TEST(Cli, HelpForEachCommand) {
  TempDir dir;
  const std::vector<std::pair<std::string, std::vector<std::string>>> commands = {
      {"delaunay", {"--output", "--neighbors", "--stats", "--variant", "--threads", "--quiet", "full, scan"}},
      {"check", {"--quiet", "qdelaunay i"}},
      {"hull", {"--output", "--neighbors", "--coplanar", "--stats", "--quiet", "qconvex i"}},
      {"generate", {"--seed", "--output", "uniform", "ball", "sphere", "gaussian", "clustered", "grid"}},
  };
  for (const auto& [command, words] : commands) {
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{command, "--help"}, {command, "-h"}, {"help", command}}) {
      const CliRun run = run_cli(dir, args);
      EXPECT_EQ(run.code, 0) << command;
      EXPECT_TRUE(contains(run.out, "Usage: drange " + command)) << command;
      EXPECT_TRUE(contains(run.out, "Exit codes:")) << command;
      EXPECT_TRUE(contains(run.out, "  3   input error")) << command;
      for (const std::string& word : words) EXPECT_TRUE(contains(run.out, word)) << command << ": " << word;
    }
  }
}

TEST(Cli, NoCommandIsAUsageError) {
  TempDir dir;
  const CliRun run = run_cli(dir, {});
  EXPECT_EQ(run.code, 2);
  EXPECT_TRUE(contains(run.err, "Usage: drange COMMAND"));
}

TEST(Cli, UnknownCommand) {
  TempDir dir;
  const CliRun run = run_cli(dir, {"triangulate"});
  EXPECT_EQ(run.code, 2);
  EXPECT_EQ(run.err,
            "drange: unknown command 'triangulate' (expected delaunay, voronoi, check, hull, generate or help)\n"
            "Try 'drange --help'.\n");
}

TEST(Cli, UnknownOptionNamesItAndTheCommand) {
  TempDir dir;
  const CliRun run = run_cli(dir, {"generate", "uniform", "10", "3", "--bogus"});
  EXPECT_EQ(run.code, 2);
  EXPECT_EQ(run.err, "drange: unknown option '--bogus'\nTry 'drange generate --help'.\n");
  EXPECT_EQ(run_cli(dir, {"--bogus"}).code, 2);
}

TEST(Cli, MissingOptionValue) {
  TempDir dir;
  const CliRun run = run_cli(dir, {"generate", "uniform", "10", "3", "-o"});
  EXPECT_EQ(run.code, 2);
  EXPECT_EQ(run.err, "drange: option '-o' needs a value\nTry 'drange generate --help'.\n");
}

TEST(Cli, FlagWithAValue) {
  TempDir dir;
  const CliRun run = run_cli(dir, {"check", "a", "b", "--quiet=yes"});
  EXPECT_EQ(run.code, 2);
  EXPECT_EQ(run.err, "drange: option '--quiet' takes no value\nTry 'drange check --help'.\n");
}

TEST(Cli, MissingAndExtraArguments) {
  TempDir dir;
  CliRun run = run_cli(dir, {"check", "points.txt"});
  EXPECT_EQ(run.code, 2);
  EXPECT_EQ(run.err, "drange: missing argument SIMPLICES\nTry 'drange check --help'.\n");
  run = run_cli(dir, {"generate", "uniform", "10", "3", "extra"});
  EXPECT_EQ(run.code, 2);
  EXPECT_EQ(run.err, "drange: unexpected argument 'extra'\nTry 'drange generate --help'.\n");
  run = run_cli(dir, {"delaunay", "a.txt", "b.txt"});
  EXPECT_EQ(run.code, 2);
  EXPECT_EQ(run.err, "drange: unexpected argument 'b.txt'\nTry 'drange delaunay --help'.\n");
}

TEST(Cli, BadArgumentValues) {
  TempDir dir;
  CliRun run = run_cli(dir, {"generate", "normal", "10", "3"});
  EXPECT_EQ(run.code, 2);
  EXPECT_TRUE(contains(run.err, "unknown distribution 'normal' (expected one of: uniform, ball"));
  run = run_cli(dir, {"generate", "uniform", "1e6", "3"});
  EXPECT_EQ(run.code, 2);
  EXPECT_TRUE(contains(run.err, "drange: N must be an integer from 0 to"));
  run = run_cli(dir, {"generate", "uniform", "10", "0"});
  EXPECT_EQ(run.code, 2);
  EXPECT_TRUE(contains(run.err, "drange: D must be an integer from 1 to"));
  run = run_cli(dir, {"generate", "uniform", "10", "3", "--seed", "-1"});
  EXPECT_EQ(run.code, 2);
  EXPECT_TRUE(contains(run.err, "drange: the seed must be an integer from 0 to 18446744073709551615, got '-1'"));
}

TEST(Cli, DelaunayOutputOptionsWithoutInput) {
  TempDir dir;
  const CliRun run = run_cli(dir, {"delaunay", "-o", dir.file("out.txt")});
  EXPECT_EQ(run.code, 2);
  EXPECT_TRUE(contains(run.err, "--output needs an INPUT file"));
}

TEST(Cli, DelaunaySameFileTwice) {
  TempDir dir;
  write_text(dir.file("p.txt"), kSquareWithCentre);
  const CliRun run = run_cli(dir, {"delaunay", dir.file("p.txt"), "-o", dir.file("x"), "--neighbors", dir.file("x")});
  EXPECT_EQ(run.code, 2);
  EXPECT_TRUE(contains(run.err, "--output and --neighbors name the same file"));
}

// ---------------------------------------------------------------- generate

TEST(Cli, GenerateWritesQhullFormatIdenticalToTheLibrary) {
  TempDir dir;
  const CliRun run = run_cli(dir, {"generate", "gaussian", "50", "3", "--seed", "7", "-o", dir.file("p.txt")});
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(run.out, "");
  const PointCloud back = read_points(dir.file("p.txt"));
  const PointCloud want = generate_points(Distribution::Gaussian, 50, 3, 7);
  EXPECT_EQ(back.dim, 3);
  EXPECT_EQ(back.coords, want.coords);
  EXPECT_EQ(read_text(dir.file("p.txt")).substr(0, 5), "3\n50\n");
}

TEST(Cli, GenerateToStandardOutput) {
  TempDir dir;
  const CliRun run = run_cli(dir, {"generate", "grid", "4", "2"});
  EXPECT_EQ(run.code, 0);
  EXPECT_EQ(run.out, "2\n4\n0 0\n0 1\n1 0\n1 1\n");
  // Default seed 1, -s as a short form, "-" for stdout.
  EXPECT_EQ(run_cli(dir, {"generate", "uniform", "3", "2"}).out,
            run_cli(dir, {"generate", "uniform", "3", "2", "-s", "1", "-o", "-"}).out);
  EXPECT_NE(run_cli(dir, {"generate", "uniform", "3", "2"}).out, run_cli(dir, {"generate", "uniform", "3", "2", "--seed=2"}).out);
}

// ---------------------------------------------------------------- input and output errors

TEST(Cli, MissingInputFileIsAnInputError) {
  TempDir dir;
  const CliRun run = run_cli(dir, {"delaunay", dir.file("missing.txt")});
  EXPECT_EQ(run.code, 3);
  EXPECT_EQ(run.err, "drange: cannot open '" + dir.file("missing.txt") + "': No such file or directory\n");
}

TEST(Cli, MalformedInputNamesFileAndLine) {
  TempDir dir;
  write_text(dir.file("p.txt"), "1 2\n3 4\n5 x\n");
  const CliRun run = run_cli(dir, {"delaunay", dir.file("p.txt")});
  EXPECT_EQ(run.code, 3);
  EXPECT_EQ(run.err, "drange: " + dir.file("p.txt") + ":3: not a number: \"x\"\n");
  EXPECT_EQ(run.out, "");
}

TEST(Cli, MalformedStandardInputIsNamedStdin) {
  TempDir dir;
  write_text(dir.file("p.txt"), "1 2\n3 4 5\n");
  const CliRun run = run_cli(dir, {"delaunay", "-"}, dir.file("p.txt"));
  EXPECT_EQ(run.code, 3);
  EXPECT_EQ(run.err, "drange: <stdin>:2: expected 2 coordinates, found 3\n");
}

TEST(Cli, MalformedSimplicesForCheck) {
  TempDir dir;
  write_text(dir.file("p.txt"), kSquareWithCentre);
  write_text(dir.file("s.txt"), "1\n0 1\n");
  const CliRun run = run_cli(dir, {"check", dir.file("p.txt"), dir.file("s.txt")});
  EXPECT_EQ(run.code, 3);
  EXPECT_EQ(run.err, "drange: " + dir.file("s.txt") + ":2: expected 3 indices, found 2\n");
}

TEST(Cli, CheckCannotReadBothFromStandardInput) {
  TempDir dir;
  EXPECT_EQ(run_cli(dir, {"check", "-", "-"}).code, 2);
}

TEST(Cli, UnwritableOutputIsAnInputError) {
  TempDir dir;
  const CliRun run = run_cli(dir, {"generate", "uniform", "10", "2", "-o", dir.file("no/such/dir/p.txt")});
  EXPECT_EQ(run.code, 3);
  EXPECT_EQ(run.err, "drange: cannot write '" + dir.file("no/such/dir/p.txt") + "': No such file or directory\n");
}

TEST(Cli, FailedRunLeavesTheOldOutputUntouched) {
  TempDir dir;
  write_text(dir.file("p.txt"), "1 2\nbroken\n");
  write_text(dir.file("out.txt"), "previous result\n");
  const CliRun run = run_cli(dir, {"delaunay", dir.file("p.txt"), "-o", dir.file("out.txt")});
  EXPECT_EQ(run.code, 3);
  EXPECT_EQ(read_text(dir.file("out.txt")), "previous result\n");
  EXPECT_EQ(count_entries(dir.path()), 2u);  // no temporary file left behind
}

// ---------------------------------------------------------------- with the engine

TEST(Cli, DelaunaySquareWithCentre) {
  TempDir dir;
  write_text(dir.file("p.txt"), kSquareWithCentre);
  const CliRun run = run_cli(dir, {"delaunay", dir.file("p.txt"), "-o", dir.file("s.txt")});
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(run.out, "");
  EXPECT_EQ(run.err, "");
  const std::vector<std::int32_t> simplices = read_simplices(dir.file("s.txt"), 3);
  ASSERT_EQ(simplices.size(), 12u);
  for (std::size_t s = 0; s < 4; ++s) {
    // Every triangle has the centre (point 4) as a vertex.
    EXPECT_TRUE(simplices[3 * s] == 4 || simplices[3 * s + 1] == 4 || simplices[3 * s + 2] == 4);
  }
}

TEST(Cli, DelaunayFromStandardInputToStandardOutput) {
  TempDir dir;
  write_text(dir.file("p.txt"), kSquareWithCentre);
  write_text(dir.file("p.csv"), "x,y\n0,0\n1,0\n1,1\n0,1\n0.5,0.5\n");
  const CliRun from_file = run_cli(dir, {"delaunay", dir.file("p.txt")});
  const CliRun from_stdin = run_cli(dir, {"delaunay", "-"}, dir.file("p.txt"));
  const CliRun from_csv = run_cli(dir, {"delaunay", dir.file("p.csv")});
  ASSERT_EQ(from_file.code, 0) << from_file.err;
  EXPECT_EQ(from_stdin.code, 0);
  EXPECT_EQ(from_file.out.substr(0, 2), "4\n");
  EXPECT_EQ(from_stdin.out, from_file.out);
  EXPECT_EQ(from_csv.out, from_file.out);
  // Like `qdelaunay i < points`: without INPUT, redirected standard input is read.
  const CliRun redirected = run_cli(dir, {"delaunay"}, dir.file("p.txt"));
  EXPECT_EQ(redirected.code, 0) << redirected.err;
  EXPECT_EQ(redirected.out, from_file.out);
}

TEST(Cli, DelaunayNeighbors) {
  TempDir dir;
  write_text(dir.file("p.txt"), kSquareWithCentre);
  const CliRun run =
      run_cli(dir, {"delaunay", dir.file("p.txt"), "-o", dir.file("s.txt"), "--neighbors", dir.file("n.txt")});
  ASSERT_EQ(run.code, 0) << run.err;
  // read_simplices rejects -1, so the neighbours are read here.
  std::istringstream in(read_text(dir.file("n.txt")));
  std::size_t rows = 0;
  in >> rows;
  EXPECT_EQ(rows, 4u);
  std::vector<std::int32_t> neighbors;
  for (std::int32_t value = 0; in >> value;) neighbors.push_back(value);
  ASSERT_EQ(neighbors.size(), 12u);
  // Each triangle: one hull edge (-1), two neighbours.
  for (std::size_t s = 0; s < 4; ++s) {
    int hull = 0;
    for (std::size_t k = 0; k < 3; ++k) hull += neighbors[3 * s + k] == -1;
    EXPECT_EQ(hull, 1) << "simplex " << s;
  }
}

TEST(Cli, DelaunayStatsAndVariant) {
  TempDir dir;
  write_text(dir.file("p.txt"), kSquareWithCentre);
  CliRun run = run_cli(dir, {"delaunay", dir.file("p.txt"), "--stats", "--variant", "scan"});
  EXPECT_EQ(run.code, 0) << run.err;
  EXPECT_TRUE(contains(run.err, "=")) << run.err;
  run = run_cli(dir, {"delaunay", dir.file("p.txt"), "--variant", "fastest"});
  EXPECT_EQ(run.code, 2);
  EXPECT_TRUE(contains(run.err, "fastest")) << run.err;
  EXPECT_TRUE(contains(run.err, "Try 'drange delaunay --help'."));
  // Checked before anything is read or run: not the missing file's error, no demonstration.
  for (const std::vector<std::string>& args : {std::vector<std::string>{"delaunay", dir.file("missing.txt"), "--variant", "ful"},
                                               std::vector<std::string>{"delaunay", "--variant", "ful"},
                                               std::vector<std::string>{"voronoi", dir.file("missing.txt"), "--variant", "ful"}}) {
    run = run_cli(dir, args);
    EXPECT_EQ(run.code, 2) << args[1];
    EXPECT_TRUE(contains(run.err, "--variant: unknown variant 'ful' (expected one of: full, ")) << run.err;
    EXPECT_EQ(run.out, "") << args[1];
  }
}

// --threads changes nothing in the output: the same bytes for the simplices, the neighbours and
// the Voronoi diagram.
TEST(Cli, ThreadsGiveTheSameBytes) {
  TempDir dir;
  ASSERT_EQ(run_cli(dir, {"generate", "uniform", "20000", "2", "-o", dir.file("p.txt")}).code, 0);
  for (const char* threads : {"1", "2", "5"}) {
    const std::string t = threads;
    CliRun run = run_cli(dir, {"delaunay", dir.file("p.txt"), "-o", dir.file("s" + t + ".txt"), "--neighbors",
                               dir.file("n" + t + ".txt"), "--threads", threads});
    ASSERT_EQ(run.code, 0) << run.err;
    run = run_cli(dir, {"voronoi", dir.file("p.txt"), "-o", dir.file("v" + t + ".json"), "--threads=" + t});
    ASSERT_EQ(run.code, 0) << run.err;
  }
  for (const char* threads : {"2", "5"}) {
    const std::string t = threads;
    EXPECT_EQ(read_text(dir.file("s" + t + ".txt")), read_text(dir.file("s1.txt"))) << "--threads " << t;
    EXPECT_EQ(read_text(dir.file("n" + t + ".txt")), read_text(dir.file("n1.txt"))) << "--threads " << t;
    EXPECT_EQ(read_text(dir.file("v" + t + ".json")), read_text(dir.file("v1.json"))) << "--threads " << t;
  }
  const CliRun stats = run_cli(dir, {"delaunay", dir.file("p.txt"), "-o", dir.file("s.txt"), "--stats", "--threads", "3"});
  EXPECT_TRUE(contains(stats.err, " threads=3 ")) << stats.err;
}

// The same in 3D, where `full` takes the open facets in the spatial order, and with that
// order forced in 2D; --variant fifo lists the same simplices in another order.
TEST(Cli, ThreadsGiveTheSameBytesUnderTheSpatialOrder) {
  TempDir dir;
  ASSERT_EQ(run_cli(dir, {"generate", "uniform", "8000", "3", "-o", dir.file("p3.txt")}).code, 0);
  ASSERT_EQ(run_cli(dir, {"generate", "uniform", "8000", "2", "-o", dir.file("p2.txt")}).code, 0);
  for (const auto& [input, variant] : {std::pair<std::string, std::string>{"p3.txt", "full"}, {"p2.txt", "spatial"}}) {
    std::string first;
    for (const char* threads : {"1", "2", "3", "4"}) {
      const CliRun run = run_cli(dir, {"delaunay", dir.file(input), "-o", dir.file("s.txt"), "--variant", variant, "--threads", threads});
      ASSERT_EQ(run.code, 0) << run.err;
      const std::string out = read_text(dir.file("s.txt"));
      if (first.empty()) first = out;
      EXPECT_EQ(out, first) << input << " --variant " << variant << " --threads " << threads;
    }
    ASSERT_EQ(run_cli(dir, {"delaunay", dir.file(input), "-o", dir.file("f.txt"), "--variant", "fifo"}).code, 0);
    const std::string fifo = read_text(dir.file("f.txt"));
    EXPECT_NE(fifo, first) << input;
    const std::size_t width = input == "p3.txt" ? 4 : 3;
    auto sorted = [&](const std::vector<std::int32_t>& flat) {
      std::vector<std::vector<std::int32_t>> keys;
      for (std::size_t i = 0; i < flat.size(); i += width) {
        keys.emplace_back(flat.begin() + static_cast<long>(i), flat.begin() + static_cast<long>(i + width));
        std::sort(keys.back().begin(), keys.back().end());
      }
      std::sort(keys.begin(), keys.end());
      return keys;
    };
    const int vertices = static_cast<int>(width);
    EXPECT_EQ(sorted(read_simplices(dir.file("f.txt"), vertices)), sorted(read_simplices(dir.file("s.txt"), vertices))) << input;
  }
}

TEST(Cli, BadThreadCountIsAUsageError) {
  TempDir dir;
  write_text(dir.file("p.txt"), kSquareWithCentre);
  for (const std::string command : {"delaunay", "voronoi"}) {
    for (const std::string value : {"-1", "two", "2x", "", "1025", "1.5"}) {
      const CliRun run = run_cli(dir, {command, dir.file("p.txt"), "--threads", value});
      EXPECT_EQ(run.code, 2) << command << " --threads '" << value << "'";
      EXPECT_EQ(run.err, "drange: --threads must be an integer from 0 to 1024, got '" + value + "'\nTry 'drange " +
                             command + " --help'.\n");
    }
  }
}

TEST(Cli, DelaunayReportsDuplicates) {
  TempDir dir;
  write_text(dir.file("p.txt"), "2\n7\n0 0\n1 0\n1 1\n0 1\n0.5 0.5\n0 0\n1 1\n");
  CliRun run = run_cli(dir, {"delaunay", dir.file("p.txt"), "-o", dir.file("s.txt")});
  EXPECT_EQ(run.code, 0);
  EXPECT_EQ(run.err, "drange: 2 duplicate points left out (point 5 = point 0, point 6 = point 2)\n");
  EXPECT_EQ(read_simplices(dir.file("s.txt"), 3).size(), 12u);
  run = run_cli(dir, {"delaunay", dir.file("p.txt"), "-o", dir.file("s.txt"), "--quiet"});
  EXPECT_EQ(run.code, 0);
  EXPECT_EQ(run.err, "");
}

TEST(Cli, DelaunayListsAtMostTenDuplicates) {
  TempDir dir;
  std::string text = "2\n15\n0 0\n1 0\n0 1\n";
  for (int i = 0; i < 12; ++i) text += "1 0\n";
  write_text(dir.file("p.txt"), text);
  const CliRun run = run_cli(dir, {"delaunay", dir.file("p.txt"), "-o", dir.file("s.txt")});
  EXPECT_EQ(run.code, 0);
  EXPECT_EQ(run.err,
            "drange: 12 duplicate points left out (point 3 = point 1, point 4 = point 1, point 5 = point 1, "
            "point 6 = point 1, point 7 = point 1, point 8 = point 1, point 9 = point 1, point 10 = point 1, "
            "point 11 = point 1, point 12 = point 1, ...)\n");
}

TEST(Cli, DegenerateInput) {
  TempDir dir;
  write_text(dir.file("p.txt"), "2\n3\n0 0\n1 1\n2 2\n");
  const CliRun run = run_cli(dir, {"delaunay", dir.file("p.txt"), "-o", dir.file("s.txt")});
  EXPECT_EQ(run.code, 4);
  EXPECT_TRUE(contains(run.err, "drange: ")) << run.err;
  EXPECT_EQ(count_entries(dir.path()), 1u);  // no output file
}

TEST(Cli, OneDimensionalInputIsAnInputError) {
  // drange/delaunay.hpp: a bad dimension is an InputError, a property of the data (exit 3),
  // not a mistake on the command line (exit 2, "Try 'drange delaunay --help'").
  TempDir dir;
  write_text(dir.file("p.txt"), "0.5\n1.5\n2.5\n");
  const CliRun run = run_cli(dir, {"delaunay", dir.file("p.txt")});
  EXPECT_EQ(run.code, 3) << run.err;
  EXPECT_FALSE(contains(run.err, "Try 'drange")) << run.err;
}

TEST(Cli, CheckAcceptsOurOutput) {
  TempDir dir;
  write_text(dir.file("p.txt"), kSquareWithCentre);
  ASSERT_EQ(run_cli(dir, {"delaunay", dir.file("p.txt"), "-o", dir.file("s.txt")}).code, 0);
  CliRun run = run_cli(dir, {"check", dir.file("p.txt"), dir.file("s.txt")});
  EXPECT_EQ(run.code, 0) << run.out << run.err;
  EXPECT_EQ(run.out, "valid: 4 simplices, 4 interior facets, 4 boundary facets\n");
  run = run_cli(dir, {"check", dir.file("p.txt"), dir.file("s.txt"), "--quiet"});
  EXPECT_EQ(run.code, 0);
  EXPECT_EQ(run.out, "");
  // Points from standard input.
  run = run_cli(dir, {"check", "-", dir.file("s.txt")}, dir.file("p.txt"));
  EXPECT_EQ(run.code, 0) << run.err;
}

TEST(Cli, CheckRejectsABrokenTriangulation) {
  TempDir dir;
  write_text(dir.file("p.txt"), kSquareWithCentre);
  // Two triangles split by the square's diagonal: the centre, a distinct point, is no vertex
  // (and lies on the shared edge): not a triangulation of the points.
  write_text(dir.file("s.txt"), "2\n0 1 2\n0 2 3\n");
  CliRun run = run_cli(dir, {"check", dir.file("p.txt"), dir.file("s.txt")});
  EXPECT_EQ(run.code, 1) << run.out << run.err;
  EXPECT_TRUE(contains(run.out, "invalid: ")) << run.out;
  run = run_cli(dir, {"check", dir.file("p.txt"), dir.file("s.txt"), "-q"});
  EXPECT_EQ(run.code, 1);
  EXPECT_EQ(run.out, "");
}

TEST(Cli, CheckAgreesWithAGeneratedRun) {
  TempDir dir;
  ASSERT_EQ(run_cli(dir, {"generate", "uniform", "300", "3", "-o", dir.file("p.txt")}).code, 0);
  const CliRun triangulate = run_cli(dir, {"delaunay", dir.file("p.txt"), "-o", dir.file("s.txt")});
  ASSERT_EQ(triangulate.code, 0) << triangulate.err;
  const CliRun check = run_cli(dir, {"check", dir.file("p.txt"), dir.file("s.txt")});
  EXPECT_EQ(check.code, 0) << check.out;
  EXPECT_EQ(check.out.substr(0, 7), "valid: ");
}

}  // namespace
}  // namespace drange
