// `polydem analytic fragility` and `polydem analytic synthetic` end to end,
// in-process: the files they write, determinism of the written bits, and
// bad input refused with the file, line or option before anything is written.
#include "apps/analytic_command.hpp"
#include "io/record_suite.hpp"

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace fs = std::filesystem;

namespace {

struct Ran {
  int rc;
  std::string out, err;
};

Ran run(const std::vector<std::string>& a) {
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  Ran r;
  r.rc = run_analytic_command(a);
  r.out = testing::internal::GetCapturedStdout();
  r.err = testing::internal::GetCapturedStderr();
  return r;
}

std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

// The tests' files, under one temporary folder removed at exit.
struct ScratchRoot {
  fs::path path = fs::temp_directory_path() / ("polydem_fragility_cmd_" + std::to_string(::getpid()));
  ~ScratchRoot() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

fs::path scratch(const std::string& name) {
  static const ScratchRoot root;
  const fs::path d = root.path / name;
  fs::remove_all(d);
  fs::create_directories(d.parent_path());
  return d;
}

void write(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << text;
}

// An IDA of six records: capacities for collapse 0.3 ... 0.8, damage at
// half of them; the sixth never collapses up to 0.9.
std::string ida_csv() {
  std::string s = "# record, IM (PGA in g), worst state\nrecord,im,state\n";
  const double collapse[] = {0.3, 0.4, 0.45, 0.55, 0.8};
  for (int i = 0; i < 5; ++i) {
    std::string r(1, 'r');
    r += std::to_string(i);
    s += r + "," + std::to_string(collapse[i] / 2) + ",damaged\n";
    s += r + "," + std::to_string(collapse[i]) + ",collapsed\n";
  }
  s += "r5,0.2,intact\nr5,0.9,stones_lost\n";
  return s;
}

}  // namespace

TEST(SyntheticCommand, WritesASuiteAndTheSameSeedGivesTheSameBits) {
  const fs::path a = scratch("suite_a"), b = scratch("suite_b");
  const std::vector<std::string> args = {"analytic", "synthetic", "--magnitude", "6", "--distance", "30",
                                         "--vs30",   "600",       "--count",     "3", "--seed",     "42"};
  auto with_out = [&](const fs::path& d) {
    auto v = args;
    v.push_back("--out");
    v.push_back(d.string());
    return v;
  };
  const Ran r = run(with_out(a));
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.out.find("synthetic_03"), std::string::npos);
  for (const char* f : {"synthetic_01.csv", "synthetic_02.csv", "synthetic_03.csv", "suite.toml", "records.csv"})
    EXPECT_TRUE(fs::exists(a / f)) << f;
  const std::string csv = slurp(a / "synthetic_02.csv");
  EXPECT_NE(csv.find("# units: m/s2\ntime_s,acceleration_m_s2\n0,0\n0.01,"), std::string::npos);
  const std::string toml = slurp(a / "suite.toml");
  EXPECT_NE(toml.find("[[record]]\nname = \"synthetic_03\"\nfile = \"synthetic_03.csv\"\ndirection = [1.0, 0.0, 0.0]\n"
                      "scale = 1.0\n"),
            std::string::npos);
  // The suite is what the suite reader takes: [suite] with its name, one
  // [[record]] per record.
  const polydem::RecordSuite read = polydem::read_record_suite((a / "suite.toml").string());
  EXPECT_EQ(read.name.rfind("synthetic M ", 0), 0u) << read.name;
  ASSERT_EQ(read.records.size(), 3u);
  EXPECT_EQ(read.records[2].name, "synthetic_03");
  const toml::table suite = toml::parse_file((a / "suite.toml").string());
  const toml::array* records = suite["record"].as_array();
  ASSERT_TRUE(records);
  ASSERT_EQ(records->size(), 3u);
  EXPECT_EQ((*records)[1].as_table()->at("file").value<std::string>(), "synthetic_02.csv");
  EXPECT_EQ((*records)[1].as_table()->at("scale").value<double>(), 1.0);
  ASSERT_EQ(run(with_out(b)).rc, 0);
  for (const char* f : {"synthetic_01.csv", "synthetic_03.csv", "suite.toml", "records.csv"})
    EXPECT_EQ(slurp(a / f), slurp(b / f)) << f;
}

TEST(SyntheticCommand, BadInputWritesNothing) {
  const fs::path d = scratch("bad_suite");
  auto error = [&](std::vector<std::string> v) {
    v.insert(v.begin(), "synthetic");
    v.push_back("--out");
    v.push_back(d.string());
    const Ran r = run(v);
    EXPECT_EQ(r.rc, 2);
    EXPECT_FALSE(fs::exists(d));
    return r.err;
  };
  EXPECT_EQ(error({"--magnitude", "-6", "--distance", "30", "--vs30", "600"}),
            "polydem analytic synthetic: --magnitude must be > 0\n");
  EXPECT_EQ(error({"--magnitude", "6", "--distance", "30", "--vs30", "600", "--count", "2.5"}),
            "polydem analytic synthetic: --count must be an integer in [1, 100000]\n");
  EXPECT_NE(error({"--distance", "30", "--vs30", "600"}).find("--magnitude is required"), std::string::npos);
  EXPECT_NE(error({"--magnitude", "6", "--distance", "30", "--vs30", "600", "--fault", "normal"}).find("--fault"),
            std::string::npos);
}

TEST(FragilityCommand, FitsIdaAndStripesAndWritesTheTables) {
  const fs::path in = scratch("in") / "ida.csv", out = scratch("ida_out");
  write(in, ida_csv());
  const Ran r = run({"fragility", in.string(), "--out", out.string(), "--bootstrap", "200", "--no-plot"});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.out.find("IDA (censored MLE)"), std::string::npos);
  const std::string par = slurp(out / "fragility_parameters.csv");
  EXPECT_NE(par.find("collapsed,fitted,ida,"), std::string::npos);
  EXPECT_NE(par.find(",6,5,200,"), std::string::npos);  // 6 records, 5 collapsed
  EXPECT_NE(slurp(out / "fragility_points.csv").find("collapsed,r5,0.9,1,0,0\n"), std::string::npos);  // censored
  EXPECT_EQ(slurp(out / "fragility_curves.csv").rfind("state,im,probability,low,high\ndamaged,0,0,", 0), 0u);

  // Without the record column the same runs are stripes (one run each).
  const fs::path msa = scratch("in2") / "msa.csv";
  write(msa, "im,state\n0.1,intact\n0.1,intact\n0.2,damaged\n0.2,intact\n0.3,collapsed\n0.3,damaged\n0.4,collapsed\n"
             "0.4,collapsed\n");
  const Ran s = run({"fragility", msa.string(), "--out", scratch("msa_out").string(), "--json", "--bootstrap", "50",
                     "--no-plot"});
  ASSERT_EQ(s.rc, 0) << s.err;
  EXPECT_NE(s.out.find("\"method\":\"stripes\""), std::string::npos);
  EXPECT_NE(s.out.find("\"state\":\"stones_lost\",\"status\":\"fitted\""), std::string::npos);
}

TEST(FragilityCommand, DrawsThePngWhenMatplotlibIsThere) {
  if (std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "/usr/bin/python3 without matplotlib";
  const fs::path in = scratch("in3") / "ida.csv", out = scratch("png_out");
  write(in, ida_csv());
  const Ran r = run({"fragility", in.string(), "--out", out.string(), "--bootstrap", "50", "--im-label", "PGA [g]"});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_GT(fs::file_size(out / "fragility.png"), 10000u);
}

TEST(FragilityCommand, BadInputNamesFileAndLineAndWritesNothing) {
  const fs::path dir = scratch("bad"), out = scratch("bad_out");
  auto error = [&](const std::string& text, std::vector<std::string> extra = {}) {
    const fs::path in = dir / "runs.csv";
    write(in, text);
    std::vector<std::string> v = {"fragility", in.string(), "--out", out.string(), "--no-plot"};
    v.insert(v.end(), extra.begin(), extra.end());
    const Ran r = run(v);
    EXPECT_EQ(r.rc, 2);
    EXPECT_FALSE(fs::exists(out));
    const std::string prefix = "polydem analytic fragility: ";
    return r.err.rfind(prefix, 0) == 0 ? r.err.substr(prefix.size()) : r.err;
  };
  const std::string f = (dir / "runs.csv").string();
  EXPECT_EQ(error("record,im,state\na,0.2,broken\n"),
            f + ":2: state: 'broken' is not intact, damaged, stones_lost, collapsed or 0-3\n");
  EXPECT_EQ(error("# c\nrecord,im,state\na,0.2,intact\na,-0.1,collapsed\n"), f + ":4: im: must be finite and > 0 (got -0.1)\n");
  EXPECT_EQ(error("record,im,state\na,x,intact\n"), f + ":2: im: not a number: 'x'\n");
  EXPECT_EQ(error("record,pga,state\na,0.1,intact\n").find(f + ":1: the header must name the columns im and state"), 0u);
  EXPECT_EQ(error("record,im,state\na,0.1\n"), f + ":2: expected 3 columns as in the header, found 2\n");
  EXPECT_EQ(error("record,im,state\n"), f + ": no runs after the header\n");
  EXPECT_EQ(error("im,state\n0.1,intact\n", {"--method", "ida"}),
            f + ": --method ida needs a record column (or use --method stripes)\n");
  EXPECT_EQ(error("im,state\n0.1,intact\n", {"--confidence", "1"}), "--confidence must be in (0, 1)\n");
  fs::remove(dir / "runs.csv");
  EXPECT_EQ(run({"fragility", (dir / "runs.csv").string(), "--out", out.string()}).err,
            "polydem analytic fragility: " + f + ": cannot open\n");
}
