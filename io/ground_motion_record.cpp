#include "io/ground_motion_record.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string_view>

namespace polydem {
namespace {

std::string format_message(const std::string& file, int line, const std::string& what) {
  if (line > 0) return file + ":" + std::to_string(line) + ": " + what;
  return file + ": " + what;
}

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string_view trim(std::string_view s) {
  const auto sp = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  while (!s.empty() && sp(s.front())) s.remove_prefix(1);
  while (!s.empty() && sp(s.back())) s.remove_suffix(1);
  return s;
}

// Lines without their terminators ("\n" or "\r\n"); a UTF-8 byte-order mark
// at the start is dropped. A final newline does not start an extra line.
std::vector<std::string_view> split_lines(std::string_view text) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.push_back(line);
    start = end + 1;
  }
  return lines;
}

std::vector<std::string_view> split_whitespace(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    const std::size_t b = i;
    while (i < s.size() && !std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    if (i > b) out.push_back(s.substr(b, i - b));
  }
  return out;
}

enum class NumberParse { Ok, NotANumber, NotFinite };

// Whole token as a double. Accepts a leading '+' and Fortran 'D' exponents.
NumberParse parse_number(std::string_view token, double& out) {
  std::string t(token);
  if (!t.empty() && t.front() == '+') t.erase(0, 1);
  for (char& c : t)
    if (c == 'D' || c == 'd') c = 'E';
  if (t.empty()) return NumberParse::NotANumber;
  const char* first = t.data();
  const char* last = t.data() + t.size();
  const auto r = std::from_chars(first, last, out, std::chars_format::general);
  if (r.ptr != last) return NumberParse::NotANumber;
  if (r.ec == std::errc::result_out_of_range) return NumberParse::NotFinite;
  if (r.ec != std::errc()) return NumberParse::NotANumber;
  return std::isfinite(out) ? NumberParse::Ok : NumberParse::NotFinite;
}

// Ground accelerations beyond this are not a record but a typo or a unit
// error; the cap also keeps every difference of two samples finite.
constexpr double kMaxAccelerationG = 1000.0;

// Each unit's name and size in m/s², in the order of AccelerationUnit.
struct UnitRow {
  const char* name;
  double metres_per_second_squared;
};
constexpr UnitRow kUnits[] = {{"g", kRecordG}, {"m/s2", 1.0}, {"cm/s2", 0.01}};

const char* unit_text(AccelerationUnit unit) { return kUnits[static_cast<int>(unit)].name; }

void check_acceleration(const std::string& name, int line, double value, AccelerationUnit unit, double scale) {
  const double value_g = unit == AccelerationUnit::g ? value : value * metres_per_second_squared(unit) / kRecordG;
  if (!(std::abs(value_g * scale) <= kMaxAccelerationG)) {
    std::ostringstream os;
    os << "acceleration " << value << " " << unit_text(unit) << " (times scale " << scale << ") exceeds "
       << kMaxAccelerationG << " g: not a ground motion (units?)";
    throw RecordError(name, line, os.str());
  }
}

// The values after a header: `n` numbers, any number per line, from line
// index `first` on, in `unit`, times `scale`. `declared` says where n comes
// from ("line 4 declares NPTS=1560") for the messages.
std::vector<double> read_values(const std::vector<std::string_view>& lines, std::size_t first, std::size_t n,
                                const std::string& name, AccelerationUnit unit, double scale,
                                const std::string& declared, int header_line, const std::string& text) {
  std::vector<double> out;
  // Reserve no more than the text can hold: a header cannot make us allocate
  // gigabytes before a single value is read.
  out.reserve(std::min(n, text.size() / 2 + 1));
  const double factor = scale * metres_per_second_squared(unit);
  int last_data_line = header_line;
  for (std::size_t i = first; i < lines.size(); ++i) {
    const int line_no = static_cast<int>(i) + 1;
    for (const auto token : split_whitespace(lines[i])) {
      if (out.size() == n)
        throw RecordError(name, line_no,
                          "extra values: " + declared + " but more follow ('" + std::string(token) +
                              "' would be value " + std::to_string(n + 1) + ")");
      double v = 0;
      switch (parse_number(token, v)) {
        case NumberParse::NotANumber:
          throw RecordError(name, line_no, "non-numeric value '" + std::string(token) + "'");
        case NumberParse::NotFinite:
          throw RecordError(name, line_no, "NaN/inf value '" + std::string(token) + "'");
        case NumberParse::Ok: break;
      }
      check_acceleration(name, line_no, v, unit, scale);
      out.push_back(v * factor);
      last_data_line = line_no;
    }
  }
  if (out.size() < n)
    throw RecordError(name, last_data_line,
                      "truncated data: " + declared + " but only " + std::to_string(out.size()) + " values follow");
  return out;
}

void check_scale(const std::string& name, double scale) {
  if (!std::isfinite(scale)) throw RecordError(name, 0, "scale factor must be finite");
}

// ---------------------------------------------------------------- PEER AT2

// The characters a number in the header can be made of.
std::string_view number_at(std::string_view s, std::size_t pos) {
  while (pos < s.size() && (s[pos] == ' ' || s[pos] == '\t')) ++pos;
  std::size_t end = pos;
  while (end < s.size() && (std::isdigit(static_cast<unsigned char>(s[end])) || std::strchr("+-.eE", s[end]) != nullptr))
    ++end;
  return s.substr(pos, end - pos);
}

// Value after "KEY =" (case-insensitive) in an upper-cased line; empty when
// the key is not followed by '='.
std::string_view value_after_key(std::string_view up, std::string_view key) {
  std::size_t pos = 0;
  while ((pos = up.find(key, pos)) != std::string_view::npos) {
    std::size_t p = pos + key.size();
    while (p < up.size() && (up[p] == ' ' || up[p] == '\t')) ++p;
    if (p < up.size() && up[p] == '=') return number_at(up, p + 1);
    pos += key.size();
  }
  return {};
}

struct At2Header {
  long npts = 0;
  double dt = 0;
};

At2Header parse_at2_npts_dt(std::string_view line, const std::string& name) {
  constexpr int kLine = 4;
  const std::string up = upper(line);
  const std::string example =
      " (expected e.g. 'NPTS=   1560, DT= 0.02000 SEC' or '1560    0.0200    NPTS, DT'), found '" +
      std::string(trim(line)) + "'";
  if (up.find("NPTS") == std::string::npos)
    throw RecordError(name, kLine, "wrong header: line 4 must give NPTS and DT" + example);
  std::string_view npts_text, dt_text;
  if (up.find('=') != std::string::npos) {
    npts_text = value_after_key(up, "NPTS");
    dt_text = value_after_key(up, "DT");
  } else {
    std::string cleaned = up;
    std::replace(cleaned.begin(), cleaned.end(), ',', ' ');
    const auto tokens = split_whitespace(cleaned);
    if (tokens.size() >= 2) {
      // Positions in `up` match positions in `cleaned`.
      npts_text = std::string_view(up).substr(static_cast<std::size_t>(tokens[0].data() - cleaned.data()), tokens[0].size());
      dt_text = std::string_view(up).substr(static_cast<std::size_t>(tokens[1].data() - cleaned.data()), tokens[1].size());
    }
  }
  if (npts_text.empty() || dt_text.empty())
    throw RecordError(name, kLine, "wrong header: cannot find NPTS and DT" + example);

  At2Header h;
  double npts = 0;
  const auto np = parse_number(npts_text, npts);
  if (np == NumberParse::NotANumber || (np == NumberParse::Ok && npts != std::floor(npts)))
    throw RecordError(name, kLine, "wrong header: NPTS '" + std::string(npts_text) + "' is not an integer");
  if (np == NumberParse::NotFinite || npts <= 0)
    throw RecordError(name, kLine, "NPTS must be positive, found '" + std::string(npts_text) + "'");
  if (npts > 1e9) throw RecordError(name, kLine, "NPTS " + std::string(npts_text) + " is implausibly large");
  h.npts = static_cast<long>(npts);
  const auto dp = parse_number(dt_text, h.dt);
  if (dp == NumberParse::NotANumber)
    throw RecordError(name, kLine, "wrong header: DT '" + std::string(dt_text) + "' is not a number");
  if (dp == NumberParse::NotFinite || h.dt <= 0)
    throw RecordError(name, kLine, "DT must be positive and finite, found '" + std::string(dt_text) + "'");
  return h;
}

// Line 3 says what the series is and its unit ("ACCELERATION TIME SERIES IN
// UNITS OF G"). Reject velocity/displacement files and units other than g.
void check_at2_units_line(std::string_view line, const std::string& name) {
  const std::string up = upper(line);
  if (up.find("VELOCITY") != std::string::npos || up.find("DISPLACEMENT") != std::string::npos)
    throw RecordError(name, 3, "wrong header: not an acceleration record ('" + std::string(trim(line)) + "')");
  const auto pos = up.find("UNITS OF");
  if (pos == std::string::npos) return;  // older files do not say; PEER acceleration is in g
  const auto tokens = split_whitespace(std::string_view(up).substr(pos + 8));
  if (tokens.empty() || tokens[0] != "G")
    throw RecordError(name, 3,
                      "wrong header: acceleration must be in units of g ('" + std::string(trim(line)) + "')");
}

// ---------------------------------------------------------------- CSV

std::vector<std::string_view> split_csv_fields(std::string_view line) {
  if (line.find(',') == std::string_view::npos) return split_whitespace(line);
  std::vector<std::string_view> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    out.push_back(trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return out;
}

// "time_s", "time (s)", "Time[s]", "t" -> (name, unit) in lower case.
std::pair<std::string, std::string> header_name_unit(std::string_view field) {
  const std::string f = lower(trim(field));
  auto open = f.find_first_of("([");
  if (open != std::string::npos) {
    const auto close = f.find_first_of(")]", open);
    const std::string unit = f.substr(open + 1, close == std::string::npos ? std::string::npos : close - open - 1);
    return {std::string(trim(f.substr(0, open))), std::string(trim(unit))};
  }
  const auto us = f.find('_');
  if (us != std::string::npos) return {f.substr(0, us), f.substr(us + 1)};
  return {f, ""};
}

const std::string kUnitChoices = "g, m/s2 or cm/s2";

AccelerationUnit unit_or_fail(std::string_view text, const std::string& name, int line_no, const std::string& where) {
  const auto unit = acceleration_unit_named(text);
  if (!unit)
    throw RecordError(name, line_no,
                      "unknown acceleration unit '" + std::string(text) + "' " + where + " (expected " + kUnitChoices +
                          ")");
  return *unit;
}

// The header line's acceleration unit, if it names one.
std::optional<AccelerationUnit> check_csv_header(const std::vector<std::string_view>& fields, std::string_view line,
                                                 const std::string& name, int line_no) {
  const std::string expected =
      "wrong header: expected two columns time and acceleration with its unit ('time_s,acceleration_g', "
      "'time_s,acceleration_m_s2' or 'time_s,acceleration_cm_s2'), found '" +
      std::string(trim(line)) + "'";
  if (fields.size() != 2) throw RecordError(name, line_no, expected);
  const auto [tname, tunit] = header_name_unit(fields[0]);
  const auto [aname, aunit] = header_name_unit(fields[1]);
  const bool time_ok = tname == "time" || tname == "t";
  const bool acc_ok = aname.rfind("acc", 0) == 0 || aname == "a";
  if (!time_ok || !acc_ok) throw RecordError(name, line_no, expected);
  if (!(tunit.empty() || tunit == "s" || tunit == "sec"))
    throw RecordError(name, line_no, "wrong header: time must be in s, header says '" + tunit + "'");
  if (aunit.empty()) return std::nullopt;
  return unit_or_fail(aunit, name, line_no, "in the header");
}

// "# units: g" (or "unit", '=' for ':', any case): the declared unit text.
std::optional<std::string> units_comment(std::string_view line) {
  const std::string body = lower(trim(line.substr(1)));
  for (const std::string_view key : {"units", "unit"}) {
    if (body.rfind(key, 0) != 0) continue;
    const std::string_view rest = trim(std::string_view(body).substr(key.size()));
    if (!rest.empty() && (rest.front() == ':' || rest.front() == '=')) return std::string(trim(rest.substr(1)));
  }
  return std::nullopt;
}

// ---------------------------------------------------------------- ESM

// "KEY: value" -> (KEY upper-cased, value trimmed); nullopt when the line is
// not of that form (a data line).
std::optional<std::pair<std::string, std::string_view>> esm_header_field(std::string_view line) {
  const auto colon = line.find(':');
  if (colon == std::string_view::npos) return std::nullopt;
  const std::string_view key = trim(line.substr(0, colon));
  double v = 0;
  if (key.empty() || parse_number(key, v) != NumberParse::NotANumber) return std::nullopt;
  return std::make_pair(upper(key), trim(line.substr(colon + 1)));
}

}  // namespace

RecordError::RecordError(const std::string& file_, int line_, const std::string& what)
    : std::runtime_error(format_message(file_, line_, what)), file(file_), line(line_) {}

GroundMotionRecord parse_at2(const std::string& text, const std::string& name, double scale) {
  check_scale(name, scale);
  const auto lines = split_lines(text);
  const bool blank = std::all_of(lines.begin(), lines.end(), [](std::string_view l) { return trim(l).empty(); });
  if (blank) throw RecordError(name, 1, "empty file");
  if (lines.size() < 4)
    throw RecordError(name, static_cast<int>(lines.size()),
                      "truncated header: a PEER .AT2 file has 4 header lines, found " + std::to_string(lines.size()));
  check_at2_units_line(lines[2], name);
  const At2Header h = parse_at2_npts_dt(lines[3], name);

  GroundMotionRecord rec;
  rec.dt = h.dt;
  rec.source = name;
  const auto n = static_cast<std::size_t>(h.npts);
  if (!std::isfinite(static_cast<double>(h.npts - 1) * h.dt) || static_cast<double>(h.npts - 1) * h.dt > 1e6)
    throw RecordError(name, 4, "NPTS x DT is not a plausible duration (over 1e6 s)");
  rec.acceleration = read_values(lines, 4, n, name, AccelerationUnit::g, scale,
                                 "line 4 declares NPTS=" + std::to_string(h.npts), 4, text);
  rec.time.resize(n);
  for (std::size_t i = 0; i < n; ++i) rec.time[i] = static_cast<double>(i) * h.dt;
  return rec;
}

GroundMotionRecord parse_esm(const std::string& text, const std::string& name, double scale) {
  check_scale(name, scale);
  const auto lines = split_lines(text);
  const bool blank = std::all_of(lines.begin(), lines.end(), [](std::string_view l) { return trim(l).empty(); });
  if (blank) throw RecordError(name, 1, "empty file");
  // The header: "KEY: value" lines up to the first line of numbers. The
  // three fields read, each with its line (0 while not seen).
  struct Field {
    std::string_view text;
    int line = 0;
  };
  Field ndata, interval, units;
  std::size_t first_data = 0;
  for (; first_data < lines.size(); ++first_data) {
    const std::string_view line = trim(lines[first_data]);
    if (line.empty()) continue;
    const auto field = esm_header_field(line);
    if (!field) break;
    const int line_no = static_cast<int>(first_data) + 1;
    const auto& [key, value] = *field;
    if (key == "NDATA") ndata = {value, line_no};
    if (key == "SAMPLING_INTERVAL_S") interval = {value, line_no};
    if (key == "UNITS") units = {value, line_no};
    if (key == "DATA_TYPE" && !value.empty() && upper(value).find("ACCELERATION") == std::string::npos)
      throw RecordError(name, line_no,
                        "wrong header: not an acceleration record (DATA_TYPE: " + std::string(value) + ")");
  }
  const int header_end = static_cast<int>(first_data);
  if (first_data == 0)
    throw RecordError(name, 1, "wrong header: an ESM/ITACA file starts with 'KEY: value' lines (EVENT_NAME: ...)");
  for (const auto& [field, key] : {std::pair{&ndata, "NDATA"}, {&interval, "SAMPLING_INTERVAL_S"}, {&units, "UNITS"}})
    if (field->line == 0 || field->text.empty())
      throw RecordError(name, field->line == 0 ? header_end : field->line,
                        std::string("wrong header: no ") + key +
                            " (an ESM/ITACA header gives NDATA, SAMPLING_INTERVAL_S and UNITS)");
  const std::string_view ndata_text = ndata.text, dt_text = interval.text;
  const int ndata_line = ndata.line, dt_line = interval.line;
  double npts = 0, dt = 0;
  if (parse_number(ndata_text, npts) != NumberParse::Ok || npts != std::floor(npts) || npts <= 0 || npts > 1e9)
    throw RecordError(name, ndata_line, "NDATA must be a positive integer, found '" + std::string(ndata_text) + "'");
  if (parse_number(dt_text, dt) != NumberParse::Ok || !(dt > 0))
    throw RecordError(name, dt_line,
                      "SAMPLING_INTERVAL_S must be positive and finite, found '" + std::string(dt_text) + "'");
  const AccelerationUnit unit = unit_or_fail(units.text, name, units.line, "in UNITS");
  const auto n = static_cast<std::size_t>(npts);
  if (!((npts - 1) * dt <= 1e6))
    throw RecordError(name, ndata_line, "NDATA x SAMPLING_INTERVAL_S is not a plausible duration (over 1e6 s)");

  GroundMotionRecord rec;
  rec.dt = dt;
  rec.source = name;
  rec.acceleration = read_values(lines, first_data, n, name, unit, scale,
                                 "line " + std::to_string(ndata_line) + " declares NDATA=" + std::string(ndata_text),
                                 header_end, text);
  rec.time.resize(n);
  for (std::size_t i = 0; i < n; ++i) rec.time[i] = static_cast<double>(i) * dt;
  return rec;
}

GroundMotionRecord parse_csv_record(const std::string& text, const std::string& name, double scale) {
  check_scale(name, scale);
  const auto lines = split_lines(text);
  GroundMotionRecord rec;
  rec.source = name;
  std::optional<AccelerationUnit> unit;
  // A second declaration must agree with the first.
  const auto declare = [&](AccelerationUnit u, int line_no) {
    if (unit && *unit != u)
      throw RecordError(name, line_no,
                        std::string("acceleration unit ") + unit_text(u) + " contradicts the unit declared before (" +
                            unit_text(*unit) + ")");
    unit = u;
  };
  double factor = 0;
  bool first_content = true;
  int last_line = 1;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const int line_no = static_cast<int>(i) + 1;
    const std::string_view line = trim(lines[i]);
    if (!line.empty() && line.front() == '#' && rec.time.empty())
      if (const auto declared = units_comment(line))
        declare(unit_or_fail(*declared, name, line_no, "in the comment"), line_no);
    if (line.empty() || line.front() == '#') continue;
    last_line = line_no;
    const auto fields = split_csv_fields(line);
    double t = 0;
    if (first_content) {
      first_content = false;
      if (!fields.empty() && parse_number(fields[0], t) == NumberParse::NotANumber) {
        if (const auto u = check_csv_header(fields, line, name, line_no)) declare(*u, line_no);
        continue;
      }
    }
    if (!unit)
      throw RecordError(name, line_no,
                        "no acceleration unit declared: name it in a header line ('time_s,acceleration_g', "
                        "'time_s,acceleration_m_s2', 'time_s,acceleration_cm_s2') or in a comment before the data "
                        "('# units: g'); a record is never read as g by default");
    if (rec.time.empty()) factor = scale * metres_per_second_squared(*unit);
    if (fields.size() != 2)
      throw RecordError(name, line_no,
                        "expected 2 columns (time in s, acceleration), found " + std::to_string(fields.size()));
    double v[2] = {0, 0};
    static const char* const column[2] = {"column 1 (time)", "column 2 (acceleration)"};
    for (int c = 0; c < 2; ++c) {
      switch (parse_number(fields[static_cast<std::size_t>(c)], v[c])) {
        case NumberParse::NotANumber:
          throw RecordError(name, line_no,
                            std::string("non-numeric value '") + std::string(fields[static_cast<std::size_t>(c)]) +
                                "' in " + column[c]);
        case NumberParse::NotFinite:
          throw RecordError(name, line_no,
                            std::string("NaN/inf value '") + std::string(fields[static_cast<std::size_t>(c)]) +
                                "' in " + column[c]);
        case NumberParse::Ok: break;
      }
    }
    if (!rec.time.empty() && !(v[0] > rec.time.back())) {
      std::ostringstream os;
      os.precision(17);
      os << "time " << v[0] << " s does not increase (previous row: " << rec.time.back()
         << " s); times must be strictly increasing";
      throw RecordError(name, line_no, os.str());
    }
    if (!rec.time.empty() && !std::isfinite(v[0] - rec.time.back()))
      throw RecordError(name, line_no, "time step from the previous row is not finite");
    check_acceleration(name, line_no, v[1], *unit, scale);
    rec.time.push_back(v[0]);
    rec.acceleration.push_back(v[1] * factor);
  }
  if (rec.time.empty()) throw RecordError(name, last_line, "empty file: no data rows");
  if (rec.time.size() < 2)
    throw RecordError(name, last_line, "only one data row: a record needs at least two");
  rec.dt = rec.time[1] - rec.time[0];
  for (std::size_t i = 2; i < rec.time.size(); ++i) rec.dt = std::min(rec.dt, rec.time[i] - rec.time[i - 1]);
  return rec;
}

GroundMotionRecord read_record(const std::string& path, double scale) {
  const auto slash = path.find_last_of('/');
  const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  const auto dot = base.find_last_of('.');
  const std::string ext = dot == std::string::npos ? std::string() : lower(base.substr(dot + 1));
  if (ext != "at2" && ext != "asc" && ext != "csv")
    throw RecordError(path, 0,
                      "unknown record format: expected a PEER '.AT2', an ESM/ITACA '.ASC' or a two-column '.csv' file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw RecordError(path, 0, std::string("cannot open: ") + std::strerror(errno));
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw RecordError(path, 0, "read error");
  if (ext == "at2") return parse_at2(ss.str(), path, scale);
  if (ext == "asc") return parse_esm(ss.str(), path, scale);
  return parse_csv_record(ss.str(), path, scale);
}

double sample(const GroundMotionRecord& r, double t) {
  const std::size_t n = r.time.size();
  if (n == 0 || !(t >= r.time.front()) || t > r.time.back()) return 0.0;
  const auto it = std::upper_bound(r.time.begin(), r.time.end(), t);
  const auto i = static_cast<std::size_t>(it - r.time.begin());
  if (i >= n) return r.acceleration[n - 1];  // t == last time
  const double t0 = r.time[i - 1], t1 = r.time[i];
  const double w = (t - t0) / (t1 - t0);
  return r.acceleration[i - 1] + w * (r.acceleration[i] - r.acceleration[i - 1]);
}

double metres_per_second_squared(AccelerationUnit unit) {
  return kUnits[static_cast<int>(unit)].metres_per_second_squared;
}

std::optional<AccelerationUnit> acceleration_unit_named(std::string_view text) {
  // "m/s²" and "m/s^2" read as "m/s2".
  const std::string given = lower(trim(text));
  std::string u;
  for (std::size_t i = 0; i < given.size(); ++i) {
    if (given.compare(i, 2, "^2") == 0 || given.compare(i, 2, "\xC2\xB2") == 0) {
      u += '2';
      ++i;
    } else {
      u += given[i];
    }
  }
  if (u == "g") return AccelerationUnit::g;
  if (u == "m/s2" || u == "m/s/s" || u == "m_s2") return AccelerationUnit::m_per_s2;
  if (u == "cm/s2" || u == "cm/s/s" || u == "cm_s2" || u == "gal") return AccelerationUnit::cm_per_s2;
  return std::nullopt;
}

double peak_acceleration(const GroundMotionRecord& r) {
  double peak = 0;
  for (double a : r.acceleration) peak = std::max(peak, std::abs(a));
  return peak;
}

}  // namespace polydem
