#include "scene/field_hdf5.h"

#include <hdf5.h>

#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace vivp::scene {

namespace {

// An HDF5 identifier closed with its own function when it goes out of scope.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t), const std::string& what)
      : id_(id), close_(close) {
    if (id_ < 0) throw std::runtime_error(what);
  }
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  operator hid_t() const { return id_; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

void Check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error(what);
}

void Attribute(hid_t at, const char* name, double v, const std::string& file) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, file + ": dataspace");
  Handle a(
      H5Acreate2(at, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT),
      H5Aclose, file + ": attribute " + name);
  Check(H5Awrite(a, H5T_NATIVE_DOUBLE, &v), file + ": attribute " + name);
}

void Attribute(hid_t at, const char* name, const std::string& v,
               const std::string& file) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose, file + ": string type");
  Check(H5Tset_size(type, v.size() + 1), file + ": string type");
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, file + ": dataspace");
  Handle a(H5Acreate2(at, name, type, space, H5P_DEFAULT, H5P_DEFAULT),
           H5Aclose, file + ": attribute " + name);
  Check(H5Awrite(a, type, v.c_str()), file + ": attribute " + name);
}

double ReadNumber(hid_t at, const char* name, const std::string& file) {
  Handle a(H5Aopen(at, name, H5P_DEFAULT), H5Aclose,
           file + ": no attribute '" + name + "' (not a vivp checkpoint?)");
  double v = 0;
  Check(H5Aread(a, H5T_NATIVE_DOUBLE, &v), file + ": attribute " + name);
  return v;
}

std::string ReadText(hid_t at, const char* name, const std::string& file) {
  Handle a(H5Aopen(at, name, H5P_DEFAULT), H5Aclose,
           file + ": no attribute '" + name + "' (not a vivp checkpoint?)");
  Handle type(H5Aget_type(a), H5Tclose, file + ": attribute " + name);
  std::string v(H5Tget_size(type), '\0');
  Check(H5Aread(a, type, v.data()), file + ": attribute " + name);
  return v.substr(0, v.find('\0'));
}

void Dataset(hid_t at, const char* name, const std::vector<double>& v,
             const std::vector<hsize_t>& shape, const std::string& file) {
  Handle space(H5Screate_simple(int(shape.size()), shape.data(), nullptr),
               H5Sclose, file + ": dataspace of " + name);
  Handle d(H5Dcreate2(at, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT,
                      H5P_DEFAULT, H5P_DEFAULT),
           H5Dclose, file + ": dataset " + name);
  Check(H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()),
        file + ": dataset " + name);
}

std::vector<double> ReadDataset(hid_t at, const char* name, std::size_t n,
                                const std::string& file) {
  Handle d(H5Dopen2(at, name, H5P_DEFAULT), H5Dclose,
           file + ": no dataset '" + name + "'");
  Handle space(H5Dget_space(d), H5Sclose, file + ": dataset " + name);
  const hssize_t count = H5Sget_simple_extent_npoints(space);
  if (count < 0 || std::size_t(count) != n)
    throw std::runtime_error(file + ": dataset " + name + " has " +
                             std::to_string(count) + " values, expected " +
                             std::to_string(n));
  std::vector<double> v(n);
  Check(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()),
        file + ": dataset " + name);
  return v;
}

std::vector<double> Flat(const Eigen::MatrixXd& m) {
  return std::vector<double>(m.data(), m.data() + m.size());
}

}  // namespace

void WriteCheckpoint(const std::string& path,
                     const spacetime::FieldCheckpoint& c) {
  const std::string tmp = path + ".tmp";
  {
    Handle f(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT),
             H5Fclose, tmp + ": cannot create the checkpoint file");
    Attribute(f, "op", c.op, tmp);
    Attribute(f, "points", double(c.points), tmp);
    Attribute(f, "window_points", double(c.window_points), tmp);
    Attribute(f, "t_end", c.t_end, tmp);
    Attribute(f, "space_points", double(c.space_points), tmp);
    Attribute(f, "components", double(c.components), tmp);
    Attribute(f, "node", double(c.node), tmp);
    Attribute(f, "t", c.t, tmp);
    Attribute(f, "windows", double(c.windows), tmp);
    const hsize_t n = c.phi.size();
    Dataset(f, "phi", c.phi, {n}, tmp);
    Dataset(f, "phi_t", c.phi_t, {n}, tmp);
    Handle g(H5Gcreate2(f, "carry", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
             H5Gclose, tmp + ": group carry");
    const auto& k = c.carry;
    Attribute(g, "points", double(k.points), tmp);
    Attribute(g, "dt", k.dt, tmp);
    Attribute(g, "predictor_step", k.predictor_step, tmp);
    Attribute(g, "predictor_factor", k.predictor_factor, tmp);
    Attribute(g, "factored", double(k.modes.factored), tmp);
    Attribute(g, "valid", double(k.modes.valid), tmp);
    const hsize_t m = hsize_t(k.modes.blocks.ltt.rows());
    Dataset(g, "ltt", Flat(k.modes.blocks.ltt), {m, m}, tmp);
    Dataset(g, "lxx", Flat(k.modes.blocks.lxx), {m, m}, tmp);
    Dataset(g, "lpp", Flat(k.modes.blocks.lpp), {m, m}, tmp);
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec)
    throw std::runtime_error(path + ": cannot replace the checkpoint (" +
                             ec.message() + ")");
}

spacetime::FieldCheckpoint ReadCheckpoint(const std::string& path) {
  if (!std::filesystem::exists(path))
    throw std::runtime_error(path + ": no such checkpoint file");
  H5E_auto2_t func;
  void* data;
  H5Eget_auto2(H5E_DEFAULT, &func, &data);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // our messages, not HDF5's
  struct Restore {
    H5E_auto2_t f;
    void* d;
    ~Restore() { H5Eset_auto2(H5E_DEFAULT, f, d); }
  } restore{func, data};
  Handle f(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose,
           path + ": not an HDF5 file");
  spacetime::FieldCheckpoint c;
  c.op = ReadText(f, "op", path);
  c.points = (long long)ReadNumber(f, "points", path);
  c.window_points = (long long)ReadNumber(f, "window_points", path);
  c.t_end = ReadNumber(f, "t_end", path);
  c.space_points = int(ReadNumber(f, "space_points", path));
  c.components = int(ReadNumber(f, "components", path));
  c.node = (long long)ReadNumber(f, "node", path);
  c.t = ReadNumber(f, "t", path);
  c.windows = int(ReadNumber(f, "windows", path));
  if (c.space_points < 1 || c.components < 1 || c.components > 64)
    throw std::runtime_error(path +
                             ": space points or components out of range");
  const std::size_t n = std::size_t(c.space_points) * c.components;
  c.phi = ReadDataset(f, "phi", n, path);
  c.phi_t = ReadDataset(f, "phi_t", n, path);
  Handle g(H5Gopen2(f, "carry", H5P_DEFAULT), H5Gclose,
           path + ": no group 'carry'");
  auto& k = c.carry;
  k.points = int(ReadNumber(g, "points", path));
  k.dt = ReadNumber(g, "dt", path);
  k.predictor_step = ReadNumber(g, "predictor_step", path);
  // Absent from the checkpoints of earlier versions, which always started
  // at the default tolerance.
  if (H5Aexists(g, "predictor_factor") > 0)
    k.predictor_factor = ReadNumber(g, "predictor_factor", path);
  k.modes.factored = ReadNumber(g, "factored", path) != 0;
  k.modes.valid = ReadNumber(g, "valid", path) != 0;
  const int m = c.components;
  auto block = [&](const char* name) {
    const auto v = ReadDataset(g, name, std::size_t(m) * m, path);
    return Eigen::MatrixXd(Eigen::Map<const Eigen::MatrixXd>(v.data(), m, m));
  };
  k.modes.blocks = {block("ltt"), block("lxx"), block("lpp")};
  return c;
}

void WriteFieldSlices(const std::string& path,
                      const sbp::SpaceGrid<double>& grid, int m,
                      const std::vector<double>& t,
                      const std::vector<double>& phi,
                      const std::vector<double>& phi_t) {
  const std::size_t per = std::size_t(grid.points()) * m;
  if (phi.size() != t.size() * per ||
      (!phi_t.empty() && phi_t.size() != phi.size()))
    throw std::runtime_error(path + ": " + std::to_string(t.size()) +
                             " slices need " + std::to_string(t.size() * per) +
                             " values of φ and φ_t");
  if (std::filesystem::exists(path))
    throw std::runtime_error(path + ": exists; not overwritten");
  Handle f(H5Fcreate(path.c_str(), H5F_ACC_EXCL, H5P_DEFAULT, H5P_DEFAULT),
           H5Fclose, path + ": cannot create the file");
  std::vector<hsize_t> shape{t.size()};
  for (int a = grid.dim() - 1; a >= 0; --a) shape.push_back(grid.points(a));
  shape.push_back(hsize_t(m));
  Dataset(f, "t", t, {t.size()}, path);
  Dataset(f, "phi", phi, shape, path);
  if (!phi_t.empty()) Dataset(f, "phi_t", phi_t, shape, path);
  Attribute(f, "components", double(m), path);
  for (int a = 0; a < grid.dim(); ++a) {
    const std::string name = "axis" + std::to_string(a);
    const auto& ax = grid.axis(a);
    Attribute(f, (name + "_first").c_str(), ax.x(0), path);
    Attribute(f, (name + "_dx").c_str(), ax.dx(), path);
    Attribute(f, (name + "_points").c_str(), double(ax.points()), path);
    Attribute(f, (name + "_kind").c_str(),
              std::string(ax.periodic() ? "periodic" : "interval"), path);
  }
}

}  // namespace vivp::scene
