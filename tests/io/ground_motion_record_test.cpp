#include "io/ground_motion_record.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>

#include "tests/test_util.hpp"

namespace polydem {
namespace {

const std::string kElCentro = std::string(POLYDEM_SHARED_DIR) + "/data/elcentro-1940-ns.AT2";

#define SKIP_WITHOUT_EL_CENTRO()                                                                            \
  if (!std::filesystem::exists(kElCentro))                                                                \
  GTEST_SKIP() << "shared test data not found: " << kElCentro                                             \
               << " (the El Centro record lives in ../shared/data beside the checkout; not in the repo)"

std::string at2(const std::string& line4, const std::string& data,
                const std::string& line3 = "ACCELERATION TIME SERIES IN UNITS OF G") {
  return "PEER NGA STRONG MOTION DATABASE RECORD\nTEST EVENT, TEST STATION\n" + line3 + "\n" + line4 + "\n" + data;
}

// Expects parse to throw RecordError whose message is "name:line: ..." and
// mentions `needle`.
template <class Parse>
void expect_error(Parse parse, const std::string& name, int line, const std::string& needle) {
  try {
    parse();
    ADD_FAILURE() << "expected RecordError for " << name << " (" << needle << ")";
  } catch (const RecordError& e) {
    const std::string msg = e.what();
    const std::string prefix = name + ":" + std::to_string(line) + ": ";
    EXPECT_EQ(msg.rfind(prefix, 0), 0u) << "message: " << msg << "\nexpected prefix: " << prefix;
    EXPECT_NE(msg.find(needle), std::string::npos) << "message: " << msg << "\nexpected to mention: " << needle;
    EXPECT_EQ(e.file, name);
    EXPECT_EQ(e.line, line);
  }
}

TEST(GroundMotionRecord, ReadsElCentro) {
  SKIP_WITHOUT_EL_CENTRO();
  const GroundMotionRecord r = read_record(kElCentro);
  ASSERT_EQ(r.acceleration.size(), 1560u);
  ASSERT_EQ(r.time.size(), 1560u);
  EXPECT_DOUBLE_EQ(r.dt, 0.02);
  EXPECT_DOUBLE_EQ(r.time.front(), 0.0);
  EXPECT_NEAR(r.time.back(), 1559 * 0.02, 1e-12);
  EXPECT_EQ(r.source, kElCentro);
  EXPECT_NEAR(peak_acceleration(r) / kRecordG, 0.319, 0.001);
  // Second value of the file is 6.3e-3 g.
  EXPECT_NEAR(r.acceleration[1], 6.3e-3 * kRecordG, 1e-15);
  const GroundMotionRecord twice = read_record(kElCentro, 2.0);
  EXPECT_NEAR(peak_acceleration(twice) / kRecordG, 0.638, 0.002);
}

TEST(GroundMotionRecord, ExtensionIsCaseInsensitive) {
  SKIP_WITHOUT_EL_CENTRO();
  test::ScratchDir dir("record");
  std::filesystem::copy_file(kElCentro, dir.path("copy.at2"));  // scratch copy, removed after the test
  EXPECT_EQ(read_record(dir.path("copy.at2")).acceleration.size(), 1560u);
}

TEST(GroundMotionRecord, At2HeaderStyles) {
  const std::string data = "0.1 -0.2 0.3\n0.4\n  -0.5\n";
  for (const std::string line4 :
       {"NPTS=      5, DT= 0.01000 SEC", "NPTS=  5, DT=   .0100 SEC,", "   5    0.0100    NPTS, DT",
        "npts=5 dt=0.01 sec"}) {
    SCOPED_TRACE(line4);
    const auto r = parse_at2(at2(line4, data), "t.AT2");
    ASSERT_EQ(r.acceleration.size(), 5u);
    EXPECT_DOUBLE_EQ(r.dt, 0.01);
    EXPECT_DOUBLE_EQ(r.acceleration[4], -0.5 * kRecordG);
    EXPECT_DOUBLE_EQ(r.time[4], 0.04);
  }
  // Fortran exponents, '+' signs and CRLF line ends.
  const auto r = parse_at2(at2("NPTS= 3, DT= 0.5 SEC", "+1.0D-01 -2.5E-01\r\n.5\r\n"), "t.AT2", 2.0);
  EXPECT_DOUBLE_EQ(r.acceleration[0], 0.2 * kRecordG);
  EXPECT_DOUBLE_EQ(r.acceleration[2], 1.0 * kRecordG);
}

TEST(GroundMotionRecord, At2ErrorsNameFileAndLine) {
  const std::string n = "bad.AT2";
  const auto p = [&](const std::string& text) { return [=] { (void)parse_at2(text, n); }; };
  expect_error(p(at2("NPTS= 5, DT= 0.01 SEC", "0.1 0.2\n0.3 0.4\n")), n, 6, "truncated data");
  expect_error(p(at2("NPTS= 5, DT= 0.01 SEC", "0.1 0.2\n0.3 0.4 0.5\n0.6\n")), n, 7, "extra values");
  expect_error(p(at2("DT= 0.01 SEC", "0.1\n")), n, 4, "wrong header");
  expect_error(p(at2("0.1 0.2 0.3", "0.1\n")), n, 4, "wrong header");
  expect_error(p(at2("NPTS= 2, DT= 0.01 SEC", "0.1\n", "VELOCITY TIME SERIES IN UNITS OF CM/S")), n, 3,
               "not an acceleration record");
  expect_error(p(at2("NPTS= 2, DT= 0.01 SEC", "0.1\n", "ACCELERATION IN UNITS OF CM/S/S")), n, 3, "units of g");
  expect_error(p(at2("NPTS= 3, DT= 0.01 SEC", "0.1\n0.2 abc\n")), n, 6, "non-numeric value 'abc'");
  expect_error(p(at2("NPTS= 3, DT= 0.01 SEC", "0.1 0.2\n0.3-0.4\n")), n, 6, "non-numeric");
  expect_error(p(at2("NPTS= 3, DT= 0.01 SEC", "0.1 nan 0.2\n")), n, 5, "NaN/inf");
  expect_error(p(at2("NPTS= 3, DT= 0.01 SEC", "0.1 0.2 -inf\n")), n, 5, "NaN/inf");
  expect_error(p(at2("NPTS= 3, DT= 0.01 SEC", "0.1 0.2 1e999\n")), n, 5, "NaN/inf");
  expect_error(p(at2("NPTS= 0, DT= 0.01 SEC", "")), n, 4, "NPTS must be positive");
  expect_error(p(at2("NPTS= -5, DT= 0.01 SEC", "0.1\n")), n, 4, "NPTS must be positive");
  expect_error(p(at2("NPTS= 2.5, DT= 0.01 SEC", "0.1\n")), n, 4, "not an integer");
  expect_error(p(at2("NPTS= 2, DT= 0.0 SEC", "0.1 0.2\n")), n, 4, "DT must be positive");
  expect_error(p(at2("NPTS= 2, DT= -0.02 SEC", "0.1 0.2\n")), n, 4, "DT must be positive");
  expect_error(p(at2("NPTS= 2, DT= x SEC", "0.1 0.2\n")), n, 4, "wrong header");
  expect_error(p(""), n, 1, "empty file");
  expect_error(p("\n  \n"), n, 1, "empty file");
  expect_error(p("TITLE\nEVENT\n"), n, 2, "truncated header");
  // Data ends on a blank line: the error points at the last value's line.
  expect_error(p(at2("NPTS= 4, DT= 0.01 SEC", "0.1 0.2\n0.3\n\n\n")), n, 6, "only 3 values");
}

TEST(GroundMotionRecord, CsvWithHeaderAndNonUniformSteps) {
  const auto r = parse_csv_record(
      "# generated record\ntime_s,acceleration_g\n0.0, 0.0\n0.01,0.1\n0.03,-0.2\n\n0.035,0.0\n", "r.csv", 0.5);
  ASSERT_EQ(r.time.size(), 4u);
  EXPECT_NEAR(r.dt, 0.005, 1e-15);  // 0.035 - 0.03 in binary
  EXPECT_DOUBLE_EQ(r.acceleration[2], -0.1 * kRecordG);
  EXPECT_EQ(r.source, "r.csv");
}

TEST(GroundMotionRecord, CsvHeaderVariantsAndWhitespace) {
  for (const std::string header : {"# units: g\n", "time_s,acceleration_g\n", "Time (s), Acceleration (g)\n",
                                   "t acc_g\n", "# Units = G\ntime[s],accel\n", "# units: g\ntime_s,acceleration_g\n"}) {
    SCOPED_TRACE(header);
    const auto r = parse_csv_record(header + "0 0.1\n0.02 0.2\n0.04 0.3\n", "w.csv");
    ASSERT_EQ(r.time.size(), 3u);
    EXPECT_DOUBLE_EQ(r.dt, 0.02);
    EXPECT_DOUBLE_EQ(r.acceleration[1], 0.2 * kRecordG);
  }
}

TEST(GroundMotionRecord, CsvErrorsNameFileAndLine) {
  const std::string n = "bad.csv";
  const auto p = [&](const std::string& text) { return [=] { (void)parse_csv_record(text, n); }; };
  expect_error(p("time_s,acceleration_g\n0,0\n0.02,0.1\n0.02,0.2\n"), n, 4, "strictly increasing");
  const std::string g = "# units: g\n";  // line 1
  expect_error(p(g + "0,0\n0.02,0.1\n0.01,0.2\n"), n, 4, "strictly increasing");
  expect_error(p(g + "0,0\n0.02,abc\n"), n, 3, "non-numeric value 'abc' in column 2");
  expect_error(p(g + "0,0\nx,0.1\n"), n, 3, "non-numeric value 'x' in column 1");
  expect_error(p(g + "0,0\n0.02,nan\n"), n, 3, "NaN/inf");
  expect_error(p(g + "0,0\ninf,0.1\n"), n, 3, "NaN/inf");
  expect_error(p(g + "0,0\n0.02,0.1,7\n"), n, 3, "expected 2 columns");
  expect_error(p(g + "0,0\n0.02\n"), n, 3, "expected 2 columns");
  expect_error(p("time_s,acceleration_mps\n0,0\n0.02,0.1\n"), n, 1, "unknown acceleration unit 'mps'");
  expect_error(p("# units: ft/s2\n0,0\n0.02,0.1\n"), n, 1, "unknown acceleration unit 'ft/s2'");
  expect_error(p("time_ms,acceleration_g\n0,0\n0.02,0.1\n"), n, 1, "time must be in s");
  expect_error(p("\n# comment\nfoo,bar\n0,0\n"), n, 3, "wrong header");
  expect_error(p("time,acceleration,velocity\n0,0\n"), n, 1, "wrong header");
  expect_error(p(""), n, 1, "empty file");
  expect_error(p("time_s,acceleration_g\n"), n, 1, "empty file");
  expect_error(p("time_s,acceleration_g\n0,0.1\n"), n, 2, "at least two");
}

// A two-column file must say what its acceleration is in; g, m/s² and cm/s²
// read the same motion.
TEST(GroundMotionRecord, CsvUnitMustBeDeclared) {
  const std::string n = "quake.csv";
  const auto p = [&](const std::string& text) { return [=] { (void)parse_csv_record(text, n); }; };
  expect_error(p("0,0\n0.02,0.1\n"), n, 1, "no acceleration unit declared");
  expect_error(p("# a record\n\ntime_s,acceleration\n0,0\n0.02,0.1\n"), n, 4, "no acceleration unit declared");
  expect_error(p("# units: m/s2\ntime_s,acceleration_g\n0,0\n0.02,0.1\n"), n, 2, "contradicts");
  const std::string rows_g = "0,0.1\n0.02,-0.2\n";
  const std::string rows_m = "0,0.980665\n0.02,-1.96133\n";
  const std::string rows_cm = "0,98.0665\n0.02,-196.133\n";
  const std::vector<GroundMotionRecord> same = {
      parse_csv_record("time_s,acceleration_g\n" + rows_g, n),
      parse_csv_record("time_s,acceleration_m_s2\n" + rows_m, n),
      parse_csv_record("time (s), acceleration (m/s^2)\n" + rows_m, n),
      parse_csv_record("# units: m/s²\n" + rows_m, n),
      parse_csv_record("time_s,acceleration_cm_s2\n" + rows_cm, n),
      parse_csv_record("# units: gal\n" + rows_cm, n),
      parse_csv_record("# units: cm/s^2\ntime_s,acceleration_cm_s2\n" + rows_cm, n)};
  for (const auto& r : same) {
    ASSERT_EQ(r.acceleration.size(), 2u);
    EXPECT_NEAR(r.acceleration[0], 0.1 * kRecordG, 1e-14);
    EXPECT_NEAR(r.acceleration[1], -0.2 * kRecordG, 1e-14);
  }
  // The plausibility cap is in g whatever the unit.
  expect_error(p("time_s,acceleration_cm_s2\n0,0\n0.02,2e6\n"), n, 3, "exceeds 1000 g");
  EXPECT_NO_THROW((void)parse_csv_record("time_s,acceleration_cm_s2\n0,0\n0.02,9e5\n", n));
}

// An ESM/ITACA ASCII file: the header's SAMPLING_INTERVAL_S, NDATA and UNITS.
std::string esm(const std::string& units, const std::string& ndata, const std::string& data,
                const std::string& type = "ACCELERATION") {
  return "EVENT_NAME: CENTRAL_ITALY\nEVENT_ID: EMSC-20161030_0000029\nEVENT_DATE_YYYYMMDD: 20161030\n"
         "STATION_CODE: NRC\nSAMPLING_INTERVAL_S: 0.005000\nNDATA: " +
         ndata + "\nDURATION_S: 0.015\nSTREAM: HNE\nUNITS: " + units +
         "\nPGA_CM/S^2: 2.5\nDATA_TYPE: " + type + "\nPROCESSING: manual\nUSER5:\n" + data;
}

TEST(GroundMotionRecord, ReadsEsmAscii) {
  const auto r = parse_esm(esm("cm/s^2", "4", "0.0\n1.5\n-2.5 1.0\n"), "IT.NRC..HNE.D.20161030.064018.C.ACC.ASC", 2.0);
  ASSERT_EQ(r.acceleration.size(), 4u);
  EXPECT_DOUBLE_EQ(r.dt, 0.005);
  EXPECT_DOUBLE_EQ(r.time[3], 0.015);
  EXPECT_DOUBLE_EQ(r.acceleration[2], -2.5 * 0.01 * 2.0);
  const auto g = parse_esm(esm("g", "2", "0.1 0.2\n"), "g.ASC");
  EXPECT_DOUBLE_EQ(g.acceleration[1], 0.2 * kRecordG);
  const std::string n = "e.ASC";
  const auto p = [&](const std::string& text) { return [=] { (void)parse_esm(text, n); }; };
  expect_error(p(esm("cm/s^2", "4", "0 1 2\n")), n, 14, "only 3 values");
  expect_error(p(esm("cm/s^2", "2", "0 1 2\n")), n, 14, "extra values");
  expect_error(p(esm("mm/s", "2", "0 1\n")), n, 9, "unknown acceleration unit 'mm/s'");
  expect_error(p(esm("cm/s", "2", "0 1\n", "VELOCITY")), n, 11, "not an acceleration record");
  expect_error(p(esm("cm/s^2", "-2", "0 1\n")), n, 6, "NDATA must be a positive integer");
  expect_error(p(esm("cm/s^2", "", "0 1\n")), n, 6, "no NDATA");
  expect_error(p(esm("", "2", "0 1\n")), n, 9, "no UNITS");
  expect_error(p("0.1\n0.2\n"), n, 1, "starts with 'KEY: value' lines");
  expect_error(p(""), n, 1, "empty file");
}

// Mutations of a valid ESM file (bytes changed, dropped, repeated): each
// either reads as a record that keeps the header's promises or is refused
// with a RecordError.
TEST(GroundMotionRecord, EsmMutationsReadOrAreRefused) {
  const std::string valid = esm("cm/s^2", "6", "0.0 1.5\n-2.5 1.0\n3e2 -1e-3\n");
  const std::string alphabet = "0123456789.-+eE: \n\tNDATUS_/^gcm";
  std::mt19937 rng(2016);
  int read = 0, refused = 0;
  for (int k = 0; k < 3000; ++k) {
    std::string text = valid;
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int e = 0; e < edits; ++e) {
      const std::size_t at = rng() % (text.size() + 1);
      switch (rng() % 3) {
        case 0: if (at < text.size()) text[at] = alphabet[rng() % alphabet.size()]; break;
        case 1: if (at < text.size()) text.erase(at, 1 + rng() % 8); break;
        default: text.insert(at, text.substr(rng() % text.size(), 1 + rng() % 12)); break;
      }
    }
    try {
      const GroundMotionRecord r = parse_esm(text, "m.ASC");
      ++read;
      ASSERT_EQ(r.time.size(), r.acceleration.size());
      ASSERT_TRUE(r.dt > 0 && std::isfinite(r.dt));
      for (std::size_t i = 0; i < r.time.size(); ++i) {
        ASSERT_TRUE(std::isfinite(r.time[i]) && std::isfinite(r.acceleration[i])) << text;
        if (i > 0) {
          ASSERT_GT(r.time[i], r.time[i - 1]) << text;
        }
      }
    } catch (const RecordError& e) {
      ++refused;
      EXPECT_EQ(std::string(e.what()).rfind("m.ASC:", 0), 0u) << e.what();
    }
  }
  EXPECT_GT(read, 100);
  EXPECT_GT(refused, 100);
}

TEST(GroundMotionRecord, ReadRecordReportsFileProblems) {
  test::ScratchDir dir("record");
  const std::string missing = dir.path("missing.AT2");
  try {
    (void)read_record(missing);
    FAIL() << "expected RecordError";
  } catch (const RecordError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(missing + ": cannot open", 0), 0u) << e.what();
  }
  test::write_text(dir.path("r.txt"), "0,0\n");
  EXPECT_THROW((void)read_record(dir.path("r.txt")), RecordError);
  test::write_text(dir.path("r.CSV"), "# units: g\n0,0.1\n0.5,0.2\n");
  const auto r = read_record(dir.path("r.CSV"));
  EXPECT_EQ(r.source, dir.path("r.CSV"));
  EXPECT_DOUBLE_EQ(r.dt, 0.5);
  test::write_text(dir.path("r.ASC"), esm("cm/s^2", "2", "1 2\n"));
  EXPECT_DOUBLE_EQ(read_record(dir.path("r.ASC")).acceleration[1], 0.02);
  // Errors from the file name the file path.
  test::write_text(dir.path("bad.csv"), "time_s,acceleration_g\n0,0\n0,1\n");
  try {
    (void)read_record(dir.path("bad.csv"));
    FAIL() << "expected RecordError";
  } catch (const RecordError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(dir.path("bad.csv") + ":3: ", 0), 0u) << e.what();
  }
}

TEST(GroundMotionRecord, SampleInterpolatesAndIsZeroOutside) {
  GroundMotionRecord r;
  r.time = {0.0, 0.1, 0.3};
  r.acceleration = {1.0, 3.0, -1.0};
  EXPECT_DOUBLE_EQ(sample(r, -0.01), 0.0);
  EXPECT_DOUBLE_EQ(sample(r, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(sample(r, 0.05), 2.0);
  EXPECT_DOUBLE_EQ(sample(r, 0.1), 3.0);
  EXPECT_DOUBLE_EQ(sample(r, 0.2), 1.0);
  EXPECT_DOUBLE_EQ(sample(r, 0.3), -1.0);
  EXPECT_DOUBLE_EQ(sample(r, 0.3000001), 0.0);
  EXPECT_DOUBLE_EQ(sample(r, std::nan("")), 0.0);
  EXPECT_DOUBLE_EQ(sample(GroundMotionRecord{}, 0.0), 0.0);
}

TEST(GroundMotionRecord, SampleElCentroAtGridPoints) {
  SKIP_WITHOUT_EL_CENTRO();
  const auto r = read_record(kElCentro);
  for (std::size_t i = 0; i < r.time.size(); i += 97) EXPECT_DOUBLE_EQ(sample(r, r.time[i]), r.acceleration[i]);
  EXPECT_DOUBLE_EQ(sample(r, 40.0), 0.0);
}

}  // namespace
}  // namespace polydem
