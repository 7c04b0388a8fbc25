#include "io/json.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>

namespace polydem {
namespace {

TEST(Json, EscapesStrings) {
  EXPECT_EQ(Json("plain").dump(), "\"plain\"");
  EXPECT_EQ(Json("say \"hi\"").dump(), R"("say \"hi\"")");
  EXPECT_EQ(Json("back\\slash").dump(), R"("back\\slash")");
  EXPECT_EQ(Json("a\nb\tc\rd\be\ff").dump(), R"("a\nb\tc\rd\be\ff")");
  EXPECT_EQ(Json(std::string("\x01\x1f", 2)).dump(), R"("\u0001\u001f")");
  EXPECT_EQ(Json(std::string("nul\0x", 5)).dump(), R"("nul\u0000x")");
  EXPECT_EQ(Json("Wälder °C / ok").dump(), "\"Wälder °C / ok\"");  // UTF-8 passes through
  // Keys are escaped too.
  Json o = Json::object();
  o["k\"ey"] = 1;
  EXPECT_EQ(o.dump(0), R"({"k\"ey":1})");
}

TEST(Json, NonFiniteNumbersAreNull) {
  EXPECT_EQ(Json(std::numeric_limits<double>::quiet_NaN()).dump(), "null");
  EXPECT_EQ(Json(std::numeric_limits<double>::infinity()).dump(), "null");
  EXPECT_EQ(Json(-std::numeric_limits<double>::infinity()).dump(), "null");
  Json a = Json::array();
  a.push_back(1.5).push_back(std::nan("")).push_back(Json());
  EXPECT_EQ(a.dump(0), "[1.5,null,null]");
}

TEST(Json, NumbersRoundTripExactly) {
  EXPECT_EQ(Json(0.1).dump(), "0.1");
  EXPECT_EQ(Json(0.319).dump(), "0.319");
  EXPECT_EQ(Json(1.0).dump(), "1");
  EXPECT_EQ(Json(-0.0).dump(), "-0");
  EXPECT_EQ(Json(1234567890123LL).dump(), "1234567890123");
  EXPECT_EQ(Json(-7).dump(), "-7");
  EXPECT_EQ(Json(std::size_t{42}).dump(), "42");
  std::mt19937_64 rng(12345);
  std::uniform_int_distribution<std::uint64_t> bits;
  int tested = 0;
  while (tested < 2000) {
    const std::uint64_t b = bits(rng);
    double x;
    std::memcpy(&x, &b, sizeof x);
    if (!std::isfinite(x)) continue;
    ++tested;
    const std::string s = Json(x).dump();
    const double back = std::strtod(s.c_str(), nullptr);
    ASSERT_EQ(std::memcmp(&back, &x, sizeof x), 0) << s;
    ASSERT_LE(s.size(), 24u) << s;
  }
  for (double x : {5e-324, 1.7976931348623157e308, 1.0 / 3.0, 9.80665, 1e21, 123456789.123456789}) {
    const std::string s = Json(x).dump();
    EXPECT_EQ(std::strtod(s.c_str(), nullptr), x) << s;
  }
}

// A fixed number of significant digits applies to every double of the
// document, nested too, and to no integer; non-finite stays null.
TEST(Json, SignificantDigitsAreThoseOfPrintf) {
  Json o = Json::object();
  o.set("third", 1.0 / 3.0).set("big", 3e10).set("small", 2.5e-7).set("count", 123456789012345LL);
  o.set("list", Json(std::vector<double>{0.1, 1.0 / 7.0, std::nan("")}));
  EXPECT_EQ(o.dump(0, 12),
            R"({"third":0.333333333333,"big":30000000000,"small":2.5e-07,"count":123456789012345,)"
            R"("list":[0.1,0.142857142857,null]})");
  EXPECT_EQ(json_number(1.0 / 3.0, 4), "0.3333");
  EXPECT_EQ(json_number(1.0 / 3.0), "0.3333333333333333");
  EXPECT_EQ(Json(1.0 / 3.0).dump(2, 0), Json(1.0 / 3.0).dump());
}

TEST(Json, ObjectsKeepInsertionOrderAndReplaceInPlace) {
  Json o = Json::object();
  o["zeta"] = 1;
  o["alpha"] = 2;
  o["mid"] = 3;
  o["alpha"] = "two";
  EXPECT_EQ(o.dump(0), R"({"zeta":1,"alpha":"two","mid":3})");
  ASSERT_NE(o.find("mid"), nullptr);
  EXPECT_EQ(o.find("mid")->as_integer(), 3);
  EXPECT_EQ(o.find("missing"), nullptr);
  EXPECT_EQ(o.size(), 3u);
  EXPECT_EQ(o.keys(), (std::vector<std::string>{"zeta", "alpha", "mid"}));
}

TEST(Json, EmptyContainersAndScalars) {
  EXPECT_EQ(Json().dump(), "null");
  EXPECT_EQ(Json(true).dump(), "true");
  EXPECT_EQ(Json(false).dump(), "false");
  EXPECT_EQ(Json::object().dump(), "{}");
  EXPECT_EQ(Json::array().dump(), "[]");
  EXPECT_EQ(Json(std::vector<double>{1, 2.5}).dump(0), "[1,2.5]");
}

TEST(Json, WrongTypeAccessThrows) {
  Json s("text");
  EXPECT_THROW(s["key"], std::logic_error);
  EXPECT_THROW(s.push_back(1), std::logic_error);
  EXPECT_THROW(s.as_number(), std::logic_error);
  EXPECT_THROW(Json(1.5).as_integer(), std::logic_error);
  EXPECT_DOUBLE_EQ(Json(3).as_number(), 3.0);
  EXPECT_THROW(Json::array().at(0), std::out_of_range);
}

TEST(Json, SummaryLayoutPrettyPrinted) {
  Json summary = Json::object();
  summary["status"] = "collapsed";
  Json& checks = summary["checks"] = Json::array();
  checks.push_back(Json::object()
                       .set("name", "collapse_acceleration_g")
                       .set("measured", 0.25)
                       .set("expected", 0.2)
                       .set("tolerance", 0.1)
                       .set("passed", false));
  summary["steps"] = 1000;
  summary["energy_error"] = std::nan("");
  const std::string expected = R"({
  "status": "collapsed",
  "checks": [
    {
      "name": "collapse_acceleration_g",
      "measured": 0.25,
      "expected": 0.2,
      "tolerance": 0.1,
      "passed": false
    }
  ],
  "steps": 1000,
  "energy_error": null
})";
  EXPECT_EQ(summary.dump(), expected);
  EXPECT_EQ(summary.dump(4).find("    \"status\""), 2u);
  EXPECT_EQ(summary.dump(0).find('\n'), std::string::npos);
}

TEST(Json, ParsesWhatItWrites) {
  Json o = Json::object();
  o.set("status", "collapsed").set("steps", 123456789012LL).set("dt", 9.4e-6).set("nan", std::nan(""));
  o.set("flag", true).set("none", Json());
  Json& a = o["list"] = Json::array();
  a.push_back(1.5).push_back("say \"hi\"\n\t\x01").push_back(Json::object().set("k", -0.0));
  for (int indent : {0, 2}) {
    const Json back = Json::parse(o.dump(indent));
    EXPECT_EQ(back.dump(indent), o.dump(indent));
    EXPECT_EQ(back.find("steps")->as_integer(), 123456789012LL);
    EXPECT_EQ(back.find("dt")->as_number(), 9.4e-6);  // bit for bit: shortest round-trip text
    EXPECT_TRUE(back.find("nan")->is_null());
    EXPECT_EQ(back.find("list")->at(1).as_string(), "say \"hi\"\n\t\x01");
  }
}

TEST(Json, ParsesEscapesAndNumbers) {
  const Json j = Json::parse(R"( {"u":"\u00e9\u20ac\ud83d\ude00\/","big":1e400,"i":-17,"x":2.5E-3,"z":0} )");
  EXPECT_EQ(j.find("u")->as_string(), "\xc3\xa9\xe2\x82\xac\xf0\x9f\x98\x80/");
  EXPECT_TRUE(std::isinf(j.find("big")->as_number()));
  EXPECT_EQ(j.find("i")->as_integer(), -17);
  EXPECT_EQ(j.find("x")->as_number(), 2.5e-3);
  EXPECT_EQ(j.find("z")->type(), Json::Type::Integer);
  EXPECT_EQ(Json::parse("99999999999999999999").type(), Json::Type::Number);  // beyond 64 bits
}

TEST(Json, RejectsMalformedTextNamingTheOffset) {
  for (const char* bad : {"", "{", "[1,]", "{\"a\" 1}", "{\"a\":1,}", "tru", "01", "1.", "-", "1e", "\"abc",
                          "\"\\x\"", "\"\\ud800\"", "\"\\udc00\"", "[1] 2", "{a:1}", "\"tab\there\"", "nul"}) {
    try {
      (void)Json::parse(bad, "summary.json");
      ADD_FAILURE() << "accepted: " << bad;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("summary.json: invalid JSON at byte"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW((void)Json::parse(std::string(300, '[') + std::string(300, ']')), std::runtime_error);
  EXPECT_NO_THROW((void)Json::parse(std::string(200, '[') + std::string(200, ']')));
}

}  // namespace
}  // namespace polydem
