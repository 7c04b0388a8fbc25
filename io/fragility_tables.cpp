#include "io/fragility_tables.hpp"

#include "core/number_text.hpp"
#include "io/atomic_file.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace polydem {

namespace pa = analytical;

namespace {

std::string trimmed(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return std::string(s.substr(first, last - first + 1));
}

std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    out.push_back(trimmed(std::string_view(line).substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (comma == std::string::npos) return out;
    start = comma + 1;
  }
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string text(double x) { return shortest_text(x); }

}  // namespace

FragilityInput parse_fragility_runs(const std::string& content, const std::string& name) {
  FragilityInput in;
  std::istringstream lines(content);
  std::string line;
  int line_no = 0;
  std::optional<std::size_t> col_record, col_im, col_state;
  std::size_t columns = 0;
  bool header = false;
  auto fail = [&](const std::string& what) { throw std::runtime_error(name + ":" + std::to_string(line_no) + ": " + what); };
  while (std::getline(lines, line)) {
    ++line_no;
    const std::string t = trimmed(line);
    if (t.empty() || t[0] == '#') continue;
    const std::vector<std::string> f = fields_of(t);
    if (!header) {
      header = true;
      columns = f.size();
      for (std::size_t i = 0; i < f.size(); ++i) {
        const std::string c = lower(f[i]);
        std::optional<std::size_t>* slot = c == "record" ? &col_record : c == "im" ? &col_im : c == "state" ? &col_state : nullptr;
        if (!slot) continue;
        if (*slot) fail("column '" + c + "' named twice");
        *slot = i;
      }
      if (!col_im || !col_state)
        fail("the header must name the columns im and state (and record for IDA), e.g. 'record,im,state'; found '" + t +
             "'");
      in.has_records = col_record.has_value();
      continue;
    }
    if (f.size() != columns)
      fail("expected " + std::to_string(columns) + " columns as in the header, found " + std::to_string(f.size()));
    pa::FragilityRun run;
    const std::string& im = f[*col_im];
    const auto r = std::from_chars(im.data(), im.data() + im.size(), run.im);
    if (r.ec != std::errc() || r.ptr != im.data() + im.size()) fail("im: not a number: '" + im + "'");
    if (!(run.im > 0.0) || !std::isfinite(run.im)) fail("im: must be finite and > 0 (got " + im + ")");
    if (lower(f[*col_state]) == "undetermined") {  // a run that decided nothing: not fitted
      ++in.undetermined;
      continue;
    }
    const auto state = pa::damage_state_named(lower(f[*col_state]));
    if (!state) fail("state: '" + f[*col_state] + "' is not intact, damaged, stones_lost, collapsed or 0-3");
    run.state = *state;
    if (col_record) {
      run.record = f[*col_record];
      if (run.record.empty()) fail("record: empty name");
    }
    in.runs.push_back(std::move(run));
  }
  if (!header) throw std::runtime_error(name + ": empty file: no header line");
  if (in.runs.empty())
    throw std::runtime_error(name + (in.undetermined > 0 ? ": no runs but undetermined ones after the header"
                                                         : ": no runs after the header"));
  return in;
}

FragilityInput read_fragility_runs(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error(path + ": cannot open");
  std::ostringstream s;
  s << f.rdbuf();
  return parse_fragility_runs(s.str(), path);
}

void write_fragility_tables(const std::string& dir, const pa::FragilityResult& r) {
  std::filesystem::create_directories(dir);
  const pa::FragilityOptions& o = r.options;
  std::ostringstream par, cur, pts;
  par << "state,status,method,theta,beta,theta_low,theta_high,beta_low,beta_high,observations,reached,"
         "bootstrap,bootstrap_fitted,confidence,seed\n";
  cur << "state,im,probability,low,high\n";
  pts << "state,record,im,runs,reached,fraction\n";
  for (const pa::FragilityCurveFit& s : r.states) {
    const std::string st = pa::to_string(s.state);
    par << st << ',' << pa::to_string(s.status) << ',' << pa::to_string(o.method) << ',' << text(s.curve.theta) << ','
        << text(s.curve.beta) << ',' << text(s.theta_low) << ',' << text(s.theta_high) << ',' << text(s.beta_low) << ','
        << text(s.beta_high) << ',' << s.observations << ',' << s.reached << ',' << o.bootstrap << ','
        << s.bootstrap_fitted << ',' << text(o.confidence) << ',' << o.seed << '\n';
    for (std::size_t i = 0; i < r.im.size(); ++i)
      cur << st << ',' << text(r.im[i]) << ',' << text(s.probability[i]) << ',' << text(s.band_low[i]) << ','
          << text(s.band_high[i]) << '\n';
    for (const pa::FragilityPoint& p : s.points)
      pts << st << ',' << p.record << ',' << text(p.im) << ',' << p.runs << ',' << p.reached << ','
          << text(static_cast<double>(p.reached) / p.runs) << '\n';
  }
  const std::filesystem::path d(dir);
  write_file_atomic((d / "fragility_parameters.csv").string(), par.str());
  write_file_atomic((d / "fragility_curves.csv").string(), cur.str());
  write_file_atomic((d / "fragility_points.csv").string(), pts.str());
}

Json fragility_json(const pa::FragilityResult& r) {
  const pa::FragilityOptions& o = r.options;
  Json j = Json::object();
  j.set("method", pa::to_string(o.method))
      .set("bootstrap", o.bootstrap)
      .set("seed", static_cast<std::int64_t>(o.seed))
      .set("confidence", o.confidence);
  Json im = Json::array();
  for (double x : r.im) im.push_back(x);
  j.set("im", std::move(im));
  Json states = Json::array();
  for (const pa::FragilityCurveFit& s : r.states) {
    auto numbers = [](const std::vector<double>& v) {
      Json a = Json::array();
      for (double x : v) a.push_back(x);
      return a;
    };
    Json points = Json::array();
    for (const pa::FragilityPoint& p : s.points)
      points.push_back(Json::object().set("record", p.record).set("im", p.im).set("runs", p.runs).set("reached", p.reached));
    states.push_back(Json::object()
                         .set("state", pa::to_string(s.state))
                         .set("status", pa::to_string(s.status))
                         .set("theta", s.curve.theta)
                         .set("beta", s.curve.beta)
                         .set("theta_low", s.theta_low)
                         .set("theta_high", s.theta_high)
                         .set("beta_low", s.beta_low)
                         .set("beta_high", s.beta_high)
                         .set("observations", s.observations)
                         .set("reached", s.reached)
                         .set("bootstrap_fitted", s.bootstrap_fitted)
                         .set("probability", numbers(s.probability))
                         .set("low", numbers(s.band_low))
                         .set("high", numbers(s.band_high))
                         .set("points", std::move(points)));
  }
  j.set("states", std::move(states));
  return j;
}

}  // namespace polydem
