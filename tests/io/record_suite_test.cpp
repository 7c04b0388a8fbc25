// Record suite files (io/record_suite.hpp) and the deck's record keys
// baseline_order and length_scale: what they read, and every refusal naming
// the file, the line and the key.
#include "io/deck.hpp"
#include "io/ground_motion_record.hpp"
#include "io/record_processing.hpp"
#include "io/record_spectra.hpp"
#include "io/record_suite.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "tests/test_util.hpp"

namespace polydem {
namespace {

const std::string kElCentro = std::string(POLYDEM_SHARED_DIR) + "/data/elcentro-1940-ns.AT2";

const std::string kRecordG = "time_s,acceleration_g\n0,0\n0.01,0.1\n0.02,-0.2\n0.03,0.05\n0.04,0\n";
const std::string kRecordCm = "# units: cm/s2\n0,0\n0.01,50\n0.02,-30\n0.03,0\n";

struct SuiteFiles {
  test::ScratchDir dir{"suite"};
  SuiteFiles() {
    std::filesystem::create_directories(dir.path("records"));
    test::write_text(dir.path("records/a.csv"), kRecordG);
    test::write_text(dir.path("records/b.csv"), kRecordCm);
    test::write_text(dir.path("records/no_unit.csv"), "0,0\n0.01,0.1\n");
  }
  std::string write(const std::string& text) const {
    test::write_text(dir.path("suite.toml"), text);
    return dir.path("suite.toml");
  }
};

// Expects read_record_suite to refuse with "FILE:LINE: key 'KEY': ..." and `fragment`.
void expect_refused(const SuiteFiles& f, const std::string& text, int line, const std::string& key,
                    const std::string& fragment) {
  const std::string path = f.write(text);
  try {
    (void)read_record_suite(path);
    ADD_FAILURE() << "accepted; expected an error at line " << line << " key " << key;
  } catch (const DeckError& e) {
    const std::string msg = e.what();
    const std::string where = path + ":" + std::to_string(line) + ": key '" + key + "': ";
    EXPECT_EQ(msg.rfind(where, 0), 0u) << "message: " << msg << "\nexpected: " << where;
    EXPECT_NE(msg.find(fragment), std::string::npos) << "message: " << msg << "\nexpected fragment: " << fragment;
  }
}

TEST(RecordSuite, ReadsRecordsAndComponents) {
  SuiteFiles f;
  const RecordSuite s = read_record_suite(f.write(R"([suite]
name = "two records"

[[record]]
file = "records/a.csv"
scale = 2.0

[[record]]
name = "pair"
[[record.component]]
file = "records/b.csv"
direction = [0, 2, 0]
[[record.component]]
file = "records/a.csv"
direction = [0, 0, 1]
scale = 0.5
)"));
  EXPECT_EQ(s.name, "two records");
  ASSERT_EQ(s.records.size(), 2u);
  EXPECT_EQ(s.records[0].name, "a");
  EXPECT_EQ(s.records[0].line, 4);
  ASSERT_EQ(s.records[0].components.size(), 1u);
  EXPECT_DOUBLE_EQ(s.records[0].components[0].scale, 2.0);
  EXPECT_DOUBLE_EQ(s.records[0].components[0].acceleration[1], 0.1 * 9.80665);
  EXPECT_TRUE(std::filesystem::equivalent(s.records[0].components[0].record_path, f.dir.path("records/a.csv")));
  EXPECT_EQ(s.records[1].name, "pair");
  ASSERT_EQ(s.records[1].components.size(), 2u);
  EXPECT_DOUBLE_EQ(s.records[1].components[0].direction.y(), 1.0);
  EXPECT_DOUBLE_EQ(s.records[1].components[0].acceleration[1], 0.5);
  EXPECT_EQ(s.records[1].components[1].line, 13);  // its [[record.component]] line
  const auto named = records_of_suite(s);
  ASSERT_EQ(named.size(), 3u);
  EXPECT_EQ(named[0].name, "a");
  EXPECT_EQ(named[1].name, "pair.1");
  EXPECT_DOUBLE_EQ(named[0].acceleration[1], 2.0 * 0.1 * 9.80665);
  EXPECT_DOUBLE_EQ(named[2].acceleration[1], 0.5 * 0.1 * 9.80665);
}

TEST(RecordSuite, SuiteWideCorrectionAndTimeScaling) {
  SuiteFiles f;
  const RecordSuite s = read_record_suite(
      f.write("[suite]\nlength_scale = 0.25\nbaseline_order = 0\n[[record]]\nfile = \"records/a.csv\"\n"));
  const auto& c = s.records[0].components[0];
  EXPECT_DOUBLE_EQ(c.time[2], 0.01);
  auto t = std::vector<double>{0, 0.005, 0.01, 0.015, 0.02};
  auto a = std::vector<double>{0, 0.1, -0.2, 0.05, 0};
  for (double& x : a) x *= 9.80665;
  correct_baseline(t, a, 0);
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_DOUBLE_EQ(c.acceleration[i], a[i]);
}

TEST(RecordSuite, RefusesBadSuitesNamingFileLineAndKey) {
  SuiteFiles f;
  expect_refused(f, "[[record]]\nfile = \"records/a.csv\"\nscale = -1.0\n", 3, "record[1].scale", "must be > 0");
  expect_refused(f, "[[record]]\nfile = \"records/a.csv\"\n[[record]]\nfile = \"records/gone.AT2\"\n", 4,
                 "record[2].file", "file not found");
  expect_refused(f, "[[record]]\nfile = \"records/no_unit.csv\"\n", 2, "record[1].file",
                 "no_unit.csv:1: no acceleration unit declared");
  expect_refused(f, "[[record]]\nfile = \"records/a.csv\"\ndirection = [0, 0, 0]\n", 3, "record[1].direction",
                 "zero vector");
  expect_refused(f, "[[record]]\nfile = \"records/a.csv\"\nspeed = 3\n", 3, "record[1].speed", "unknown key");
  expect_refused(f, "[[record]]\nname = \"x\"\n", 1, "record[1].file", "missing");
  expect_refused(f, "[suite]\nname = \"empty\"\n", 1, "record", "at least one [[record]]");
  expect_refused(f, "[suite]\nbaseline_order = 7\n[[record]]\nfile = \"records/a.csv\"\n", 2, "suite.baseline_order",
                 "[0, 4]");
  expect_refused(f, "[suite]\nlength_scale = 0\n[[record]]\nfile = \"records/a.csv\"\n", 2, "suite.length_scale",
                 "must be > 0");
  expect_refused(f, "name = \"x\"\n[[record]]\nfile = \"records/a.csv\"\n", 1, "name", "unknown key");
  expect_refused(f, "[[record]]\nfile = \"records/a.csv\"\n[[record]]\nfile = \"records/a.csv\"\n", 4,
                 "record[2].file", "same name");
  expect_refused(f, "[[record]]\nfile = \"records/a.csv\"\n[[record.component]]\nfile = \"records/b.csv\"\n", 2,
                 "record[1].file", "not both");
  try {
    (void)read_record_suite(f.write("[[record]\n"));
    ADD_FAILURE() << "accepted bad TOML";
  } catch (const DeckError& e) {
    EXPECT_NE(std::string(e.what()).find("suite.toml:1: TOML syntax error"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)read_record_suite(f.dir.path("none.toml")), DeckError);
}

TEST(RecordSuite, ElCentroSuiteSpectrum) {
  if (!std::filesystem::exists(kElCentro))
    GTEST_SKIP() << "shared test data not found: " << kElCentro << " (../shared/data beside the checkout)";
  SuiteFiles f;
  const RecordSuite s =
      read_record_suite(f.write("[[record]]\nfile = \"" + kElCentro + "\"\n[[record]]\nname = \"twice\"\nfile = \"" +
                                kElCentro + "\"\nscale = 2.0\n"));
  const SpectraTable t = record_spectra(records_of_suite(s), {0.1, 1.0}, 0.05);
  ASSERT_TRUE(t.suite);
  // Scales 1 and 2: the median is √2 times the first, the dispersion ln 2/√2.
  EXPECT_NEAR(t.suite->median_pseudo_acceleration[1] / t.spectra[0].pseudo_acceleration[1], std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(t.suite->dispersion[0], std::log(2.0) / std::sqrt(2.0), 1e-12);
  const std::string csv = spectra_csv(t);
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "period_s,elcentro-1940-ns.psa_g,elcentro-1940-ns.psv_m_s,elcentro-1940-ns.sd_m,twice.psa_g,twice.psv_m_s,"
            "twice.sd_m,median.psa_g,median.psv_m_s,median.sd_m,dispersion");
}

// The deck's keys for one record: time scaling and baseline correction.
TEST(RecordSuite, DeckRecordKeys) {
  SuiteFiles f;
  const std::string blocks = "[[block]]\nshape = \"box\"\nsize = [1, 1, 1]\n";
  const auto deck = [&](const std::string& motion) {
    test::write_text(f.dir.path("d.toml"),
                     blocks + "[ground_motion]\nkind = \"record\"\nrecord = \"records/a.csv\"\n" + motion);
    return read_deck(f.dir.path("d.toml")).ground_motion;
  };
  EXPECT_DOUBLE_EQ(deck("").record_time[2], 0.02);
  EXPECT_DOUBLE_EQ(deck("length_scale = 0.25\n").record_time[2], 0.01);
  // A constant offset alone is all baseline: order 0 takes it out.
  std::string offset = "time_s,acceleration_g\n";
  for (int i = 0; i <= 100; ++i) offset += std::to_string(0.01 * i) + ",0.01\n";
  test::write_text(f.dir.path("records/offset.csv"), offset);
  const auto offset_deck = [&](const std::string& motion) {
    return deck("[[ground_motion.component]]\nkind = \"record\"\nrecord = \"records/offset.csv\"\n" + motion)
        .components.front();
  };
  EXPECT_NEAR(offset_deck("").record_acceleration[50], 0.01 * 9.80665, 1e-15);
  for (double a : offset_deck("baseline_order = 0\n").record_acceleration) EXPECT_NEAR(a, 0.0, 1e-14);
  const auto refused = [&](const std::string& text, int line, const std::string& key, const std::string& fragment) {
    test::write_text(f.dir.path("d.toml"), blocks + text);
    try {
      (void)read_deck(f.dir.path("d.toml"));
      ADD_FAILURE() << "accepted " << text;
    } catch (const DeckError& e) {
      const std::string where = f.dir.path("d.toml") + ":" + std::to_string(line) + ": key '" + key + "': ";
      EXPECT_EQ(std::string(e.what()).rfind(where, 0), 0u) << e.what();
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  refused("[ground_motion]\nkind = \"constant\"\nacceleration = 1\nlength_scale = 0.5\n", 7,
          "ground_motion.length_scale", "kind = \"record\" only");
  refused("[ground_motion]\nkind = \"record\"\nrecord = \"records/a.csv\"\nbaseline_order = 5\n", 7,
          "ground_motion.baseline_order", "[0, 4]");
  refused("[ground_motion]\nkind = \"record\"\nrecord = \"records/a.csv\"\nlength_scale = -1\n", 7,
          "ground_motion.length_scale", "must be > 0");
  // A record without a unit: the record's own error, its file and line.
  test::write_text(f.dir.path("d.toml"),
                   blocks + "[ground_motion]\nkind = \"record\"\nrecord = \"records/no_unit.csv\"\n");
  try {
    (void)read_deck(f.dir.path("d.toml"));
    ADD_FAILURE() << "accepted a record without a unit";
  } catch (const RecordError& e) {
    EXPECT_EQ(e.line, 1);
    EXPECT_NE(std::string(e.what()).find("no acceleration unit declared"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace polydem
