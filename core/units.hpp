// The one g of polydem, and the unit g of ground-motion records.
//
// kGravity (9.81 m/s²) is the model's g: the default gravity of a deck
// ([simulation] gravity), the g of every deck key in g (acceleration_g,
// rate_g), of every result in g (summary.json *_g, collapse accelerations,
// sweep tables) and of the paper's analytical models (section 2 uses 9.81).
//
// kRecordG (9.80665 m/s², standard gravity by the CGPM of 1901) is not a
// second g of the model but a unit: strong-motion agencies (PEER NGA .AT2,
// the CSV records) tabulate acceleration in this g, and a record is turned
// into m/s² with it once, when it is read. A record's peak in g as the
// agency gives it is peak / kRecordG; the same peak in the model's g (as
// summary.json reports) is peak / kGravity.
#pragma once

namespace polydem {

inline constexpr double kGravity = 9.81;      // m/s²: the model's g
inline constexpr double kRecordG = 9.80665;   // m/s²: the unit g of records

}  // namespace polydem
