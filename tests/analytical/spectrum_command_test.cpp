// `polydem analytic spectrum` (apps/spectrum_command.hpp): its files on the
// El Centro record, and bad input refused with a message, exit code 2 and
// nothing written.
#include "apps/analytic_command.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/test_util.hpp"

namespace {

namespace fs = std::filesystem;

const std::string kElCentro = std::string(POLYDEM_SOURCE_DIR) + "/../shared/data/elcentro-1940-ns.AT2";

int run(const std::vector<std::string>& a, std::string* out = nullptr, std::string* err = nullptr) {
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  const int rc = run_analytic_command(a);
  const std::string o = testing::internal::GetCapturedStdout();
  const std::string e = testing::internal::GetCapturedStderr();
  if (out) *out = o;
  if (err) *err = e;
  return rc;
}

std::vector<std::vector<double>> numbers(const std::string& csv, std::vector<std::string>& header) {
  std::istringstream in(polydem::test::read_text(csv));
  std::string line;
  std::getline(in, line);
  header.clear();
  std::stringstream h(line);
  for (std::string cell; std::getline(h, cell, ',');) header.push_back(cell);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::stringstream r(line);
    rows.emplace_back();
    for (std::string cell; std::getline(r, cell, ',');) {
      try {
        rows.back().push_back(std::stod(cell));
      } catch (const std::exception&) {
        rows.back().push_back(0.0);  // the mark's name
      }
    }
  }
  return rows;
}

}  // namespace

// El Centro 1940 N-S: PGA 0.319 g, and the spectrum at T -> 0 is the PGA.
TEST(SpectrumCommand, ElCentroPgaAndShortPeriodLimit) {
  if (!fs::exists(kElCentro))
    GTEST_SKIP() << "shared test data not found: " << kElCentro << " (../shared/data beside the checkout)";
  polydem::test::ScratchDir dir("spectrum");
  const std::string out_dir = dir.path("out");
  std::string out;
  ASSERT_EQ(run({"analytic", "spectrum", kElCentro, "--periods", "0.0002,0.5,1", "--out", out_dir, "--no-plot"}, &out),
            0);
  EXPECT_NE(out.find("0.3188"), std::string::npos) << out;
  std::vector<std::string> header;
  const auto rows = numbers(out_dir + "/spectra.csv", header);
  ASSERT_EQ(header.size(), 4u);
  EXPECT_EQ(header[1], "elcentro-1940-ns.psa_g");
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_NEAR(rows[0][1], 0.319, 0.001);  // PSA at T = 0.2 ms: the PGA in g
  EXPECT_GT(rows[1][1], 0.8);             // the record's strong 0.5 s content
  const auto marks = numbers(out_dir + "/marks.csv", header);
  ASSERT_EQ(marks.size(), 2u);  // the spire and the tower by default
  EXPECT_NEAR(marks[0][1], 1 / 21.6917, 1e-5);
  EXPECT_NEAR(marks[1][1], 1 / 6.8, 1e-9);
}

TEST(SpectrumCommand, SuiteWritesMedianAndPlot) {
  if (!fs::exists(kElCentro))
    GTEST_SKIP() << "shared test data not found: " << kElCentro << " (../shared/data beside the checkout)";
  polydem::test::ScratchDir dir("spectrum_suite");
  polydem::test::write_text(dir.path("suite.toml"), "[suite]\nname = \"El Centro twice\"\n[[record]]\nfile = \"" +
                                                        kElCentro + "\"\n[[record]]\nname = \"half\"\nfile = \"" +
                                                        kElCentro + "\"\nscale = 0.5\n");
  const std::string out_dir = dir.path("out");
  std::string out;
  const int rc = run({"analytic", "spectrum", "--suite", dir.path("suite.toml"), "--mark-period", "T1=0.3", "--out",
                      out_dir},
                     &out);
  std::vector<std::string> header;
  const auto rows = numbers(out_dir + "/spectra.csv", header);
  EXPECT_EQ(rows.size(), 100u);
  EXPECT_EQ(header.back(), "dispersion");
  EXPECT_NEAR(rows[10].back(), std::log(2.0) / std::sqrt(2.0), 1e-6);
  EXPECT_NE(out.find("median"), std::string::npos);
  if (fs::exists("/usr/bin/python3")) {
    EXPECT_EQ(rc, 0) << out;
    EXPECT_GT(fs::file_size(out_dir + "/spectrum.png"), 10000u);
  }
}

// Bad input: exit code 2, a message naming the problem, no output folder.
TEST(SpectrumCommand, RefusesBadInputAndWritesNothing) {
  polydem::test::ScratchDir dir("spectrum_bad");
  polydem::test::write_text(dir.path("no_unit.csv"), "0,0\n0.01,0.1\n");
  polydem::test::write_text(dir.path("ok.csv"), "time_s,acceleration_g\n0,0\n0.01,0.1\n0.02,0\n");
  polydem::test::write_text(dir.path("missing.toml"), "[[record]]\nfile = \"gone.AT2\"\n");
  polydem::test::write_text(dir.path("negative.toml"), "[[record]]\nfile = \"ok.csv\"\nscale = -2\n");
  const std::string out_dir = dir.path("out");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{dir.path("no_unit.csv")}, "no_unit.csv:1: no acceleration unit declared"},
      {{"--suite", dir.path("missing.toml")}, "missing.toml:2: key 'record[1].file': file not found"},
      {{"--suite", dir.path("negative.toml")}, "negative.toml:3: key 'record[1].scale': must be > 0"},
      {{dir.path("ok.csv"), "--periods", "0.1,0"}, "--periods: a period must be > 0 s"},
      {{dir.path("ok.csv"), "--damping", "1"}, "--damping must be in [0, 1)"},
      {{dir.path("ok.csv"), "--mark-period", "tower"}, "--mark-period expects NAME=PERIOD"},
      {{dir.path("ok.csv"), "--mark-period", "x=0"}, "the period must be > 0 s"},
      {{dir.path("ok.csv"), "--baseline-order", "9"}, "--baseline-order must be an integer in [0, 4]"},
      {{"--suite", dir.path("negative.toml"), dir.path("ok.csv")}, "one of the two"},
      {{dir.path("nothing.AT2")}, "cannot open"},
  };
  for (const auto& [words, message] : cases) {
    std::vector<std::string> args = {"analytic", "spectrum"};
    args.insert(args.end(), words.begin(), words.end());
    args.insert(args.end(), {"--out", out_dir});
    std::string err;
    EXPECT_EQ(run(args, nullptr, &err), 2) << message;
    EXPECT_NE(err.find(message), std::string::npos) << "stderr: " << err << "\nexpected: " << message;
    EXPECT_FALSE(fs::exists(out_dir)) << message;
  }
  std::string err;
  EXPECT_EQ(run({"analytic", "spectrum", dir.path("ok.csv")}, nullptr, &err), 2);
  EXPECT_NE(err.find("--out DIR is required"), std::string::npos) << err;
}
