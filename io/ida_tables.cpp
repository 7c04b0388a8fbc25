#include "io/ida_tables.hpp"

#include "core/number_text.hpp"
#include "io/atomic_file.hpp"

#include <cmath>
#include <filesystem>

namespace polydem {
namespace {

std::string text(double x) { return std::isnan(x) ? std::string("nan") : shortest_text(x); }

// A record's name as a CSV cell: no commas, quotes or line breaks.
std::string cell(const std::string& name) {
  std::string out = name;
  for (char& c : out)
    if (c == ',' || c == '"' || c == '\n' || c == '\r') c = '_';
  return out;
}

Json number_or_null(double x) { return std::isfinite(x) ? Json(x) : Json(); }

}  // namespace

std::string ida_csv(const IdaReport& report) {
  std::string out =
      "record,im,scale,state,status,collapse_mode,peak_tip_displacement_m,residual_displacement_m,"
      "peak_displacement_m,max_bed_opening_m,max_vertical_opening_m,dislodged,damage_time_s,collapse_time_s,point\n";
  for (const IdaRecord& rec : report.records)
    for (const IdaRun& run : rec.runs) {
      const PointResult& r = run.result;
      out += cell(rec.name) + ',' + text(run.im) + ',' + text(run.factor) + ',' + run.state + ',' + r.status + ',' +
             r.collapse_mode + ',' + text(r.peak_tip_displacement) + ',' + text(r.residual_displacement) + ',' +
             text(r.peak_displacement) + ',' + text(r.max_bed_opening) + ',' + text(r.max_vertical_opening) + ',' +
             std::to_string(r.dislodged) + ',' + (r.damage_time >= 0 ? text(r.damage_time) : "nan") + ',' +
             (r.collapse_time >= 0 ? text(r.collapse_time) : "nan") + ',' +
             std::filesystem::path(r.directory).filename().string() + '\n';
    }
  return out;
}

std::string capacities_csv(const IdaReport& report) {
  std::string out = "record,record_im,damage_im,stones_lost_im,collapse_im,below_collapse_im,collapse_scale,runs,"
                    "undetermined\n";
  for (const IdaRecord& r : report.records)
    out += cell(r.name) + ',' + text(r.record_im) + ',' + text(r.damage_im) + ',' + text(r.stones_im) + ',' +
           text(r.collapse_im) + ',' + text(r.below_collapse_im) + ',' + text(r.collapse_im / r.record_im) + ',' +
           std::to_string(r.runs.size()) + ',' + std::to_string(r.undetermined) + '\n';
  return out;
}

void write_ida_tables(const std::string& dir, const IdaReport& report) {
  std::filesystem::create_directories(dir);
  write_file_atomic(dir + "/ida.csv", ida_csv(report));
  write_file_atomic(dir + "/capacities.csv", capacities_csv(report));
}

Json capacities_json(const IdaReport& report) {
  Json records = Json::array();
  for (const IdaRecord& r : report.records)
    records.push_back(Json::object()
                          .set("name", r.name)
                          .set("record_im", r.record_im)
                          .set("damage_im", number_or_null(r.damage_im))
                          .set("stones_lost_im", number_or_null(r.stones_im))
                          .set("collapse_im", number_or_null(r.collapse_im))
                          .set("below_collapse_im", r.below_collapse_im)
                          .set("runs", static_cast<std::int64_t>(r.runs.size()))
                          .set("undetermined", static_cast<std::int64_t>(r.undetermined)));
  return records;
}

}  // namespace polydem
