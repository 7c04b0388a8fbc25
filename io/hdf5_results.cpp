#include "io/hdf5_results.hpp"

#include <H5Cpp.h>

#include <stdexcept>
#include <utility>

#include "io/atomic_file.hpp"

namespace polydem {
namespace {

// Quiet the HDF5 error stack printer once: we report errors ourselves.
void quiet_hdf5() {
  static const bool done = [] {
    H5::Exception::dontPrint();
    return true;
  }();
  (void)done;
}

[[noreturn]] void fail(const std::string& file, const std::string& path, const std::string& what) {
  throw std::runtime_error(file + ": " + (path.empty() ? std::string() : path + ": ") + what);
}

// "a/b//c/" -> "/a/b/c"; "" and "/" -> "/".
std::string normalise(const std::string& path) {
  std::string out;
  std::size_t i = 0;
  while (i < path.size()) {
    while (i < path.size() && path[i] == '/') ++i;
    const std::size_t b = i;
    while (i < path.size() && path[i] != '/') ++i;
    if (i > b) {
      out += '/';
      out.append(path, b, i - b);
    }
  }
  return out.empty() ? "/" : out;
}

// Prefixes "/a", "/a/b" of "/a/b/c" (not the path itself).
std::vector<std::string> parents(const std::string& norm) {
  std::vector<std::string> out;
  for (std::size_t pos = norm.find('/', 1); pos != std::string::npos; pos = norm.find('/', pos + 1))
    out.push_back(norm.substr(0, pos));
  return out;
}

H5::StrType vlen_utf8() {
  H5::StrType st(H5::PredType::C_S1, H5T_VARIABLE);
  st.setCset(H5T_CSET_UTF8);
  return st;
}

bool exists_in(const H5::H5File& f, const std::string& norm) {
  if (norm == "/") return true;
  for (const auto& p : parents(norm))
    if (!f.nameExists(p)) return false;
  return f.nameExists(norm);
}

void write_string_attribute(H5::H5Object& obj, const std::string& name, const std::string& value) {
  if (obj.attrExists(name)) obj.removeAttr(name);
  const H5::StrType st = vlen_utf8();
  H5::Attribute a = obj.createAttribute(name, st, H5::DataSpace(H5S_SCALAR));
  a.write(st, value);
}

}  // namespace

struct ResultsFile::Impl {
  TempPath tmp;
  H5::H5File file;
  bool open = false;
  bool committed = false;

  explicit Impl(const std::string& final_path) : tmp(final_path), file(create_file(tmp.path(), final_path)), open(true) {}

  static H5::H5File create_file(const std::string& temp, const std::string& final_path) {
    quiet_hdf5();
    try {
      return H5::H5File(temp, H5F_ACC_TRUNC);
    } catch (const H5::Exception& e) {
      fail(final_path, "", "cannot create HDF5 file '" + temp + "': " + e.getDetailMsg());
    }
  }

  void check_writable() const {
    if (!open) throw std::logic_error("ResultsFile '" + tmp.final_path() + "': write after commit()");
  }

  // Creates the missing groups above `norm`; replaces an existing link at norm.
  void prepare_dataset(const std::string& norm) {
    if (norm == "/") fail(tmp.final_path(), norm, "a dataset needs a name");
    for (const auto& p : parents(norm)) {
      if (!file.nameExists(p))
        file.createGroup(p);
      else if (file.childObjType(p) != H5O_TYPE_GROUP)
        fail(tmp.final_path(), norm, "'" + p + "' exists and is not a group");
    }
    if (file.nameExists(norm)) file.unlink(norm);
  }

  template <class F>
  void with_object(const std::string& norm, F&& f) {
    if (norm == "/") {
      H5::Group g = file.openGroup("/");
      f(g);
      return;
    }
    if (!exists_in(file, norm)) {
      prepare_dataset(norm);
      H5::Group g = file.createGroup(norm);
      f(g);
      return;
    }
    const H5O_type_t t = file.childObjType(norm);
    if (t == H5O_TYPE_GROUP) {
      H5::Group g = file.openGroup(norm);
      f(g);
    } else if (t == H5O_TYPE_DATASET) {
      H5::DataSet d = file.openDataSet(norm);
      f(d);
    } else {
      fail(tmp.final_path(), norm, "not a group or dataset");
    }
  }

  // float64 dataset of shape dims with attributes unit and (optional) columns.
  void write_numeric(const std::string& norm, const std::vector<double>& data, const std::vector<hsize_t>& dims,
                     const std::string& unit, const std::vector<std::string>& column_names) {
    prepare_dataset(norm);
    H5::DataSpace space(static_cast<int>(dims.size()), dims.data());
    H5::DataSet ds = file.createDataSet(norm, H5::PredType::IEEE_F64LE, space);
    if (!data.empty()) ds.write(data.data(), H5::PredType::NATIVE_DOUBLE);
    write_string_attribute(ds, "unit", unit);
    if (!column_names.empty()) {
      const H5::StrType st = vlen_utf8();
      std::vector<const char*> ptrs;
      for (const auto& c : column_names) ptrs.push_back(c.c_str());
      const hsize_t n = ptrs.size();
      H5::Attribute a = ds.createAttribute("columns", st, H5::DataSpace(1, &n));
      a.write(st, ptrs.data());
    }
  }

  template <class F>
  void guarded(const std::string& path, F&& f) {
    check_writable();
    try {
      f();
    } catch (const H5::Exception& e) {
      fail(tmp.final_path(), path, "HDF5 error in " + e.getFuncName() + ": " + e.getDetailMsg());
    }
  }
};

ResultsFile::ResultsFile(const std::string& final_path) : impl_(std::make_unique<Impl>(final_path)) {}

ResultsFile::~ResultsFile() {
  if (impl_ && impl_->open) {
    try {
      impl_->file.close();
    } catch (...) {
      // The temporary is removed below whatever state it is in.
    }
  }
  // impl_->tmp's destructor removes the temporary unless committed.
}

ResultsFile::ResultsFile(ResultsFile&&) noexcept = default;
ResultsFile& ResultsFile::operator=(ResultsFile&& other) noexcept {
  if (this != &other) {
    ResultsFile old(std::move(*this));  // closes and removes our uncommitted file
    impl_ = std::move(other.impl_);
  }
  return *this;
}

const std::string& ResultsFile::final_path() const { return impl_->tmp.final_path(); }
const std::string& ResultsFile::temporary_path() const { return impl_->tmp.path(); }
bool ResultsFile::committed() const { return impl_ && impl_->committed; }

void ResultsFile::write_string(const std::string& path, const std::string& text) {
  const std::string norm = normalise(path);
  impl_->guarded(norm, [&] {
    impl_->prepare_dataset(norm);
    const H5::StrType st = vlen_utf8();
    H5::DataSet ds = impl_->file.createDataSet(norm, st, H5::DataSpace(H5S_SCALAR));
    ds.write(text, st);
  });
}

void ResultsFile::write_strings(const std::string& path, const std::vector<std::string>& values) {
  const std::string norm = normalise(path);
  impl_->guarded(norm, [&] {
    impl_->prepare_dataset(norm);
    const H5::StrType st = vlen_utf8();
    std::vector<const char*> ptrs;
    for (const auto& v : values) ptrs.push_back(v.c_str());
    const hsize_t n = ptrs.size();
    H5::DataSet ds = impl_->file.createDataSet(norm, st, H5::DataSpace(1, &n));
    if (n > 0) ds.write(ptrs.data(), st);
  });
}

void ResultsFile::write_attribute(const std::string& path, const std::string& name, const std::string& value) {
  const std::string norm = normalise(path);
  impl_->guarded(norm, [&] { impl_->with_object(norm, [&](H5::H5Object& o) { write_string_attribute(o, name, value); }); });
}

void ResultsFile::write_attribute(const std::string& path, const std::string& name, const char* value) {
  write_attribute(path, name, std::string(value));
}

void ResultsFile::write_attribute(const std::string& path, const std::string& name, double value) {
  const std::string norm = normalise(path);
  impl_->guarded(norm, [&] {
    impl_->with_object(norm, [&](H5::H5Object& o) {
      if (o.attrExists(name)) o.removeAttr(name);
      H5::Attribute a = o.createAttribute(name, H5::PredType::IEEE_F64LE, H5::DataSpace(H5S_SCALAR));
      a.write(H5::PredType::NATIVE_DOUBLE, &value);
    });
  });
}

void ResultsFile::write_vector(const std::string& path, const std::vector<double>& values, const std::string& unit) {
  const std::string norm = normalise(path);
  impl_->guarded(norm, [&] { impl_->write_numeric(norm, values, {static_cast<hsize_t>(values.size())}, unit, {}); });
}

void ResultsFile::write_matrix(const std::string& path, const std::vector<double>& rowmajor, std::size_t rows,
                               std::size_t cols, const std::string& unit,
                               const std::vector<std::string>& column_names) {
  const std::string norm = normalise(path);
  if (rowmajor.size() != rows * cols)
    fail(final_path(), norm,
         "matrix data has " + std::to_string(rowmajor.size()) + " values, expected rows*cols = " +
             std::to_string(rows) + "*" + std::to_string(cols));
  if (!column_names.empty() && column_names.size() != cols)
    fail(final_path(), norm,
         std::to_string(column_names.size()) + " column names for " + std::to_string(cols) + " columns");
  impl_->guarded(norm, [&] {
    impl_->write_numeric(norm, rowmajor, {static_cast<hsize_t>(rows), static_cast<hsize_t>(cols)}, unit,
                         column_names);
  });
}

void ResultsFile::commit() {
  if (!impl_) throw std::logic_error("ResultsFile::commit on a moved-from object");
  impl_->guarded("", [&] {
    impl_->file.close();
    impl_->open = false;
  });
  impl_->tmp.commit();
  impl_->committed = true;
}

// ------------------------------------------------------------------ reading

namespace {

template <class F>
auto read_guarded(const std::string& file, const std::string& path, F&& f) {
  quiet_hdf5();
  try {
    H5::H5File h(file, H5F_ACC_RDONLY);
    const std::string norm = normalise(path);
    if (!exists_in(h, norm)) fail(file, norm, "no such object");
    return f(h, norm);
  } catch (const H5::Exception& e) {
    fail(file, path, "HDF5 error in " + e.getFuncName() + ": " + e.getDetailMsg());
  }
}

template <class F>
auto with_read_object(H5::H5File& h, const std::string& norm, F&& f) {
  if (norm != "/" && h.childObjType(norm) == H5O_TYPE_DATASET) {
    H5::DataSet d = h.openDataSet(norm);
    return f(static_cast<H5::H5Object&>(d));
  }
  H5::Group g = h.openGroup(norm);
  return f(static_cast<H5::H5Object&>(g));
}

}  // namespace

std::vector<double> read_vector(const std::string& file, const std::string& path) {
  return read_guarded(file, path, [&](H5::H5File& h, const std::string& norm) {
    H5::DataSet ds = h.openDataSet(norm);
    const H5T_class_t c = ds.getTypeClass();
    if (c != H5T_FLOAT && c != H5T_INTEGER) fail(file, norm, "not a numeric dataset");
    const auto n = static_cast<std::size_t>(ds.getSpace().getSimpleExtentNpoints());
    std::vector<double> out(n);
    if (n > 0) ds.read(out.data(), H5::PredType::NATIVE_DOUBLE);
    return out;
  });
}

std::vector<std::size_t> read_shape(const std::string& file, const std::string& path) {
  return read_guarded(file, path, [&](H5::H5File& h, const std::string& norm) {
    H5::DataSpace sp = h.openDataSet(norm).getSpace();
    const int rank = sp.getSimpleExtentNdims();
    std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
    if (rank > 0) sp.getSimpleExtentDims(dims.data());
    return std::vector<std::size_t>(dims.begin(), dims.end());
  });
}

std::string read_string(const std::string& file, const std::string& path) {
  return read_guarded(file, path, [&](H5::H5File& h, const std::string& norm) {
    H5::DataSet ds = h.openDataSet(norm);
    if (ds.getTypeClass() != H5T_STRING) fail(file, norm, "not a string dataset");
    std::string s;
    ds.read(s, ds.getStrType());
    return s;
  });
}

std::vector<std::string> read_strings(const std::string& file, const std::string& path) {
  return read_guarded(file, path, [&](H5::H5File& h, const std::string& norm) {
    H5::DataSet ds = h.openDataSet(norm);
    if (ds.getTypeClass() != H5T_STRING || !ds.getStrType().isVariableStr())
      fail(file, norm, "not a dataset of variable-length strings");
    const auto n = static_cast<std::size_t>(ds.getSpace().getSimpleExtentNpoints());
    std::vector<char*> buf(n, nullptr);
    const H5::StrType st = vlen_utf8();
    if (n > 0) ds.read(buf.data(), st);
    std::vector<std::string> out;
    for (char* p : buf) {
      out.emplace_back(p ? p : "");
      if (p) H5free_memory(p);
    }
    return out;
  });
}

std::string read_attribute_string(const std::string& file, const std::string& path, const std::string& name) {
  return read_guarded(file, path, [&](H5::H5File& h, const std::string& norm) {
    return with_read_object(h, norm, [&](H5::H5Object& o) {
      if (!o.attrExists(name)) fail(file, norm, "no attribute '" + name + "'");
      H5::Attribute a = o.openAttribute(name);
      if (a.getTypeClass() != H5T_STRING) fail(file, norm, "attribute '" + name + "' is not a string");
      std::string s;
      a.read(a.getStrType(), s);
      return s;
    });
  });
}

double read_attribute_double(const std::string& file, const std::string& path, const std::string& name) {
  return read_guarded(file, path, [&](H5::H5File& h, const std::string& norm) {
    return with_read_object(h, norm, [&](H5::H5Object& o) {
      if (!o.attrExists(name)) fail(file, norm, "no attribute '" + name + "'");
      H5::Attribute a = o.openAttribute(name);
      const H5T_class_t c = a.getTypeClass();
      if (c != H5T_FLOAT && c != H5T_INTEGER) fail(file, norm, "attribute '" + name + "' is not numeric");
      if (a.getSpace().getSimpleExtentNpoints() != 1) fail(file, norm, "attribute '" + name + "' is not a scalar");
      double v = 0;
      a.read(H5::PredType::NATIVE_DOUBLE, &v);
      return v;
    });
  });
}

std::vector<std::string> read_attribute_strings(const std::string& file, const std::string& path,
                                                const std::string& name) {
  return read_guarded(file, path, [&](H5::H5File& h, const std::string& norm) {
    return with_read_object(h, norm, [&](H5::H5Object& o) {
      if (!o.attrExists(name)) fail(file, norm, "no attribute '" + name + "'");
      H5::Attribute a = o.openAttribute(name);
      if (a.getTypeClass() != H5T_STRING || !a.getStrType().isVariableStr())
        fail(file, norm, "attribute '" + name + "' is not an array of variable-length strings");
      const auto n = static_cast<std::size_t>(a.getSpace().getSimpleExtentNpoints());
      std::vector<char*> buf(n, nullptr);
      const H5::StrType st = vlen_utf8();
      if (n > 0) a.read(st, buf.data());
      std::vector<std::string> out;
      for (char* p : buf) {
        out.emplace_back(p ? p : "");
        if (p) H5free_memory(p);
      }
      return out;
    });
  });
}

bool object_exists(const std::string& file, const std::string& path) {
  quiet_hdf5();
  try {
    H5::H5File h(file, H5F_ACC_RDONLY);
    return exists_in(h, normalise(path));
  } catch (const H5::Exception& e) {
    fail(file, path, "HDF5 error in " + e.getFuncName() + ": " + e.getDetailMsg());
  }
}

}  // namespace polydem
