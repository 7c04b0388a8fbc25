#include "io/synthetic_suite.hpp"

#include "core/number_text.hpp"
#include "io/atomic_file.hpp"

#include <cmath>
#include <filesystem>
#include <sstream>

namespace polydem {

namespace pa = analytical;

namespace {

std::string text(double x) { return shortest_text(x); }

std::string scenario_text(const SyntheticSuiteRun& run) {
  const pa::EarthquakeScenario& s = run.scenario;
  return "M " + text(s.magnitude) + ", R_rup " + text(s.distance) + " km, Vs30 " + text(s.vs30) + " m/s, " +
         (s.reverse ? "reverse" : "strike-slip") + " faulting, seed " + std::to_string(run.seed);
}

std::string record_csv(const SyntheticSuiteRun& run, const pa::SyntheticRecord& r) {
  const pa::SyntheticMotionParameters& p = r.parameters;
  std::ostringstream out;
  out << "# Synthetic ground motion (Rezaeian & Der Kiureghian 2010), polydem analytic synthetic\n"
      << "# scenario: " << scenario_text(run) << "; record seed " << r.seed << "\n"
      << "# targets: arias_intensity " << text(p.arias_intensity) << " m/s, d5_95 " << text(p.d5_95) << " s, t_mid "
      << text(p.t_mid) << " s, f_mid " << text(p.f_mid) << " Hz, f_slope " << text(p.f_slope) << " Hz/s, zeta_f "
      << text(p.zeta_f) << "\n"
      << "# units: m/s2\n"
      << "time_s,acceleration_m_s2\n";
  for (std::size_t i = 0; i < r.acceleration.size(); ++i) {
    const double t = std::round(static_cast<double>(i) * r.dt * 1e9) / 1e9;
    out << text(t) << ',' << text(r.acceleration[i]) << '\n';
  }
  return out.str();
}

}  // namespace

void write_synthetic_suite(const std::string& dir, const SyntheticSuiteRun& run) {
  std::filesystem::create_directories(dir);
  const std::filesystem::path d(dir);
  std::ostringstream toml, table;
  toml << "# A record suite (docs/records.md) of synthetic records made by\n"
       << "# polydem analytic synthetic (docs/fragility.md): " << scenario_text(run) << ".\n"
       << "[suite]\nname = \"synthetic " << scenario_text(run) << "\"\n";
  table << "name,file,seed,arias_intensity_m_s,d5_95_s,t_mid_s,f_mid_hz,f_slope_hz_s,zeta_f,"
           "measured_arias_intensity_m_s,measured_d5_95_s,measured_t_mid_s,pga_m_s2,pgv_m_s,samples,dt_s\n";
  for (const pa::SyntheticRecord& r : run.records) {
    const std::string file = r.name + ".csv";
    write_file_atomic((d / file).string(), record_csv(run, r));
    toml << "\n[[record]]\nname = \"" << r.name << "\"\nfile = \"" << file
         << "\"\ndirection = [1.0, 0.0, 0.0]\nscale = 1.0\n";
    const pa::SyntheticMotionParameters& p = r.parameters;
    const pa::RecordMeasures m = pa::record_measures(r.dt, r.acceleration, run.options.g);
    table << r.name << ',' << file << ',' << r.seed << ',' << text(p.arias_intensity) << ',' << text(p.d5_95) << ','
          << text(p.t_mid) << ',' << text(p.f_mid) << ',' << text(p.f_slope) << ',' << text(p.zeta_f) << ','
          << text(m.arias_intensity) << ',' << text(m.d5_95) << ',' << text(m.t45) << ',' << text(m.pga) << ','
          << text(m.pgv) << ',' << r.acceleration.size() << ',' << text(r.dt) << '\n';
  }
  write_file_atomic((d / "suite.toml").string(), toml.str());
  write_file_atomic((d / "records.csv").string(), table.str());
}

Json synthetic_suite_json(const SyntheticSuiteRun& run, bool histories) {
  const pa::EarthquakeScenario& s = run.scenario;
  const pa::SyntheticOptions& o = run.options;
  Json j = Json::object();
  j.set("scenario", Json::object()
                        .set("magnitude", s.magnitude)
                        .set("distance_km", s.distance)
                        .set("vs30_m_s", s.vs30)
                        .set("fault", s.reverse ? "reverse" : "strike-slip"));
  j.set("seed", static_cast<std::int64_t>(run.seed));
  j.set("options", Json::object()
                       .set("dt", o.dt)
                       .set("high_pass_hz", o.high_pass)
                       .set("min_frequency_hz", o.min_frequency)
                       .set("energy_end", o.energy_end)
                       .set("tail_s", o.tail));
  const pa::SyntheticMotionParameters med = pa::median_parameters(s);
  auto parameters = [](const pa::SyntheticMotionParameters& p) {
    return Json::object()
        .set("arias_intensity_m_s", p.arias_intensity)
        .set("d5_95_s", p.d5_95)
        .set("t_mid_s", p.t_mid)
        .set("f_mid_hz", p.f_mid)
        .set("f_slope_hz_s", p.f_slope)
        .set("zeta_f", p.zeta_f);
  };
  j.set("median_parameters", parameters(med));
  Json records = Json::array();
  for (const pa::SyntheticRecord& r : run.records) {
    const pa::RecordMeasures m = pa::record_measures(r.dt, r.acceleration, o.g);
    Json rec = Json::object();
    rec.set("name", r.name)
        .set("seed", static_cast<std::int64_t>(r.seed))
        .set("dt", r.dt)
        .set("parameters", parameters(r.parameters))
        .set("measured", Json::object()
                             .set("arias_intensity_m_s", m.arias_intensity)
                             .set("d5_95_s", m.d5_95)
                             .set("t_mid_s", m.t45)
                             .set("pga_m_s2", m.pga)
                             .set("pgv_m_s", m.pgv)
                             .set("residual_velocity_m_s", m.residual_velocity));
    if (histories) {
      Json a = Json::array();
      for (double x : r.acceleration) a.push_back(x);
      rec.set("acceleration_m_s2", std::move(a));
    }
    records.push_back(std::move(rec));
  }
  j.set("records", std::move(records));
  return j;
}

}  // namespace polydem
