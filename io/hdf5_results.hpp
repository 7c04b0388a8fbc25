// results.h5: the run's deck, histories and snapshots in one HDF5 file.
//
// ResultsFile writes to a temporary name beside the final path and renames it
// on commit(); a run that stops before commit() leaves no results.h5 (the
// destructor removes the temporary). Paths are HDF5 paths ("/histories/time");
// missing intermediate groups are created. Writing a dataset that already
// exists replaces it. Every numeric dataset carries a string attribute "unit"
// (SI, e.g. "s", "m/s^2", "J"; "1" for dimensionless). The layout polydem
// uses is described in docs/results.md.
//
// The HDF5 headers stay in hdf5_results.cpp (pimpl), so code including this
// header does not compile against HDF5. Errors throw std::runtime_error naming
// the file and the HDF5 path.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace polydem {

class ResultsFile {
 public:
  // Creates (truncates) the temporary file for `final_path`.
  explicit ResultsFile(const std::string& final_path);
  ~ResultsFile();
  ResultsFile(ResultsFile&&) noexcept;
  ResultsFile& operator=(ResultsFile&&) noexcept;
  ResultsFile(const ResultsFile&) = delete;
  ResultsFile& operator=(const ResultsFile&) = delete;

  const std::string& final_path() const;
  const std::string& temporary_path() const;

  // Scalar variable-length UTF-8 string dataset (e.g. "/deck" verbatim).
  void write_string(const std::string& path, const std::string& text);
  // Attribute on the group or dataset at `path` ("/" = root); a missing
  // object is created as a group. Replaces an existing attribute.
  void write_attribute(const std::string& path, const std::string& name, const std::string& value);
  void write_attribute(const std::string& path, const std::string& name, const char* value);
  void write_attribute(const std::string& path, const std::string& name, double value);
  // 1-D dataset of variable-length UTF-8 strings (e.g. a status per sweep point).
  void write_strings(const std::string& path, const std::vector<std::string>& values);
  // 1-D float64 dataset with attribute unit.
  void write_vector(const std::string& path, const std::vector<double>& values, const std::string& unit);
  // 2-D float64 dataset [rows][cols] from row-major data, attribute unit and,
  // if given (one per column), a string-array attribute "columns".
  void write_matrix(const std::string& path, const std::vector<double>& rowmajor, std::size_t rows, std::size_t cols,
                    const std::string& unit, const std::vector<std::string>& column_names = {});

  // Flush and close the file, fsync it and rename it onto final_path().
  // No writes are allowed afterwards.
  void commit();
  bool committed() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Reading back (tests, restart, post-processing). Each call opens `file`
// read-only; errors throw std::runtime_error naming file and path.
std::vector<double> read_vector(const std::string& file, const std::string& path);  // any rank, flattened row-major
std::vector<std::size_t> read_shape(const std::string& file, const std::string& path);
std::string read_string(const std::string& file, const std::string& path);
std::vector<std::string> read_strings(const std::string& file, const std::string& path);  // 1-D string dataset
std::string read_attribute_string(const std::string& file, const std::string& path, const std::string& name);
double read_attribute_double(const std::string& file, const std::string& path, const std::string& name);
std::vector<std::string> read_attribute_strings(const std::string& file, const std::string& path,
                                                const std::string& name);  // e.g. "columns"
bool object_exists(const std::string& file, const std::string& path);

}  // namespace polydem
