#include "io/hdf5_results.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "tests/test_util.hpp"

namespace polydem {
namespace {

using test::ScratchDir;
using Names = std::vector<std::string>;

TEST(ResultsFile, RoundTrip) {
  ScratchDir dir("h5");
  const std::string path = dir.path("results.h5");
  const std::string deck = "[scene]\nname = \"spire\"  # ü\n\n[run]\nend_time = 1.5\n";
  const std::vector<double> time = {0.0, 0.001, 0.002, 0.003};
  const std::vector<double> energy = {1.0,  0.5, 0.25,  //
                                      1.5,  0.4, 0.2,   //
                                      -0.0, std::numeric_limits<double>::quiet_NaN(), 1e-300,  //
                                      7.0,  8.0, 9.0};
  {
    ResultsFile f(path);
    EXPECT_NE(f.temporary_path(), path);
    EXPECT_TRUE(std::filesystem::exists(f.temporary_path()));
    f.write_string("/deck", deck);
    f.write_attribute("/", "polydem_version", "0.1.0");
    f.write_attribute("/", "dt", 2.5e-6);
    f.write_vector("/histories/time", time, "s");
    f.write_matrix("histories/energies/values", energy, 4, 3, "J", {"kinetic", "potential", "dissipated"});
    f.write_attribute("/histories/time", "description", "output times");
    f.write_attribute("/snapshots/step_000010", "time", 0.01);  // creates the group
    f.write_string("/empty", "");
    f.write_vector("/none", {}, "1");
    EXPECT_FALSE(std::filesystem::exists(path));
    f.commit();
    EXPECT_TRUE(f.committed());
    EXPECT_THROW(f.write_vector("/late", {1.0}, "m"), std::logic_error);
  }
  EXPECT_EQ(dir.entries(), Names{"results.h5"});

  EXPECT_EQ(read_string(path, "/deck"), deck);
  EXPECT_EQ(read_string(path, "/empty"), "");
  EXPECT_EQ(read_attribute_string(path, "/", "polydem_version"), "0.1.0");
  EXPECT_EQ(read_attribute_double(path, "/", "dt"), 2.5e-6);
  EXPECT_EQ(read_vector(path, "/histories/time"), time);
  EXPECT_EQ(read_shape(path, "/histories/time"), (std::vector<std::size_t>{4}));
  EXPECT_EQ(read_attribute_string(path, "/histories/time", "unit"), "s");
  EXPECT_EQ(read_attribute_string(path, "/histories/time", "description"), "output times");
  const auto back = read_vector(path, "/histories/energies/values");
  ASSERT_EQ(back.size(), energy.size());
  for (std::size_t i = 0; i < energy.size(); ++i) {
    if (std::isnan(energy[i])) {
      EXPECT_TRUE(std::isnan(back[i])) << i;
    } else {
      EXPECT_EQ(back[i], energy[i]) << i;
      EXPECT_EQ(std::signbit(back[i]), std::signbit(energy[i])) << i;
    }
  }
  EXPECT_EQ(read_shape(path, "/histories/energies/values"), (std::vector<std::size_t>{4, 3}));
  EXPECT_EQ(read_attribute_string(path, "/histories/energies/values", "unit"), "J");
  EXPECT_EQ(read_attribute_strings(path, "/histories/energies/values", "columns"),
            (Names{"kinetic", "potential", "dissipated"}));
  EXPECT_EQ(read_attribute_double(path, "/snapshots/step_000010", "time"), 0.01);
  EXPECT_TRUE(read_vector(path, "/none").empty());
  EXPECT_TRUE(object_exists(path, "/histories/energies"));
  EXPECT_FALSE(object_exists(path, "/histories/missing/deeper"));
}

TEST(ResultsFile, StringArraysRoundTrip) {
  ScratchDir dir("h5s");
  const std::string path = dir.path("sweep.h5");
  const Names status = {"intact", "collapsed", "", "damaged \xc2\xb0"};
  {
    ResultsFile f(path);
    f.write_strings("/points/status", status);
    f.write_strings("/points/none", {});
    f.commit();
  }
  EXPECT_EQ(read_strings(path, "/points/status"), status);
  EXPECT_TRUE(read_strings(path, "/points/none").empty());
  EXPECT_THROW((void)read_strings(path, "/points/missing"), std::runtime_error);
}

TEST(ResultsFile, UncommittedRunLeavesNoFile) {
  ScratchDir dir("h5");
  const std::string path = dir.path("results.h5");
  std::string temp;
  {
    ResultsFile f(path);
    temp = f.temporary_path();
    f.write_vector("/histories/time", {0.0, 1.0}, "s");
  }
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(temp));
  EXPECT_TRUE(dir.entries().empty());
}

TEST(ResultsFile, RunThatThrowsKeepsPreviousResults) {
  ScratchDir dir("h5");
  const std::string path = dir.path("results.h5");
  {
    ResultsFile f(path);
    f.write_string("/deck", "first run");
    f.commit();
  }
  try {
    ResultsFile f(path);
    f.write_string("/deck", "second run");
    throw std::runtime_error("solver blew up");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(read_string(path, "/deck"), "first run");
  EXPECT_EQ(dir.entries(), Names{"results.h5"});
}

TEST(ResultsFile, RewritingReplacesDatasetsAndAttributes) {
  ScratchDir dir("h5");
  const std::string path = dir.path("r.h5");
  {
    ResultsFile f(path);
    f.write_vector("/a/x", {1, 2, 3}, "m");
    f.write_vector("/a/x", {4, 5}, "mm");
    f.write_attribute("/a", "note", "one");
    f.write_attribute("/a", "note", "two");
    f.commit();
  }
  EXPECT_EQ(read_vector(path, "/a/x"), (std::vector<double>{4, 5}));
  EXPECT_EQ(read_attribute_string(path, "/a/x", "unit"), "mm");
  EXPECT_EQ(read_attribute_string(path, "/a", "note"), "two");
}

TEST(ResultsFile, BadInputsThrowNamingFileAndPath) {
  ScratchDir dir("h5");
  const std::string path = dir.path("r.h5");
  ResultsFile f(path);
  EXPECT_THROW(f.write_matrix("/m", {1, 2, 3}, 2, 2, "m"), std::runtime_error);
  EXPECT_THROW(f.write_matrix("/m", {1, 2, 3, 4}, 2, 2, "m", {"only one"}), std::runtime_error);
  f.write_vector("/leaf", {1.0}, "1");
  try {
    f.write_vector("/leaf/child", {1.0}, "1");  // a dataset cannot hold children
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("/leaf"), std::string::npos) << e.what();
  }
  f.commit();
  try {
    (void)read_vector(path, "/nothing/here");
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nothing/here"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)read_vector(dir.path("absent.h5"), "/x"), std::runtime_error);
  EXPECT_THROW((void)read_attribute_string(path, "/leaf", "no_such"), std::runtime_error);
}

TEST(ResultsFile, MissingDirectoryThrows) {
  ScratchDir dir("h5");
  EXPECT_THROW(ResultsFile(dir.path("no/dir/r.h5")), std::runtime_error);
  EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace polydem
