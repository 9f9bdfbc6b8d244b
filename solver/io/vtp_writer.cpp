#include "io/vtp_writer.hpp"

#include "io/atomic_file.hpp"

#include <fmt/format.h>

namespace mrsph {

void PointCloud::add_scalar(const std::string& name, const RealArray& values) {
  fields.push_back(PointField{name, 1, std::vector<double>(values.begin(), values.end())});
}

void PointCloud::add_vector(const std::string& name, const Vec2Array& values) {
  PointField f{name, 3, {}};
  f.values.reserve(values.size() * 3);
  for (const Vec2& v : values) {
    f.values.push_back(v.x());
    f.values.push_back(v.y());
    f.values.push_back(0.0);
  }
  fields.push_back(std::move(f));
}

std::string vtp_document(const PointCloud& cloud) {
  const std::size_t n = cloud.points.size();
  std::string out;
  out += "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n<PolyData>\n";
  out += fmt::format("<Piece NumberOfPoints=\"{}\" NumberOfVerts=\"{}\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n", n, n);
  out += "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const Vec2& p : cloud.points) out += fmt::format("{:.9g} {:.9g} 0\n", p.x(), p.y());
  out += "</DataArray>\n</Points>\n<PointData>\n";
  for (const PointField& f : cloud.fields) {
    out += fmt::format("<DataArray type=\"Float64\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"ascii\">\n", f.name, f.components);
    for (std::size_t k = 0; k < f.values.size(); ++k)
      out += fmt::format("{:.9g}{}", f.values[k], (k + 1) % f.components == 0 ? "\n" : " ");
    out += "</DataArray>\n";
  }
  out += "</PointData>\n<Verts>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (std::size_t k = 0; k < n; ++k) out += fmt::format("{}\n", k);
  out += "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t k = 0; k < n; ++k) out += fmt::format("{}\n", k + 1);
  out += "</DataArray>\n</Verts>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  return out;
}

void write_vtp(const std::filesystem::path& path, const PointCloud& cloud) {
  write_file_atomically(path, vtp_document(cloud));
}

void write_pvd(const std::filesystem::path& path, const std::vector<PvdEntry>& entries) {
  std::string out = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (const PvdEntry& e : entries)
    out += fmt::format("<DataSet timestep=\"{:.9g}\" part=\"0\" file=\"{}\"/>\n", e.time, e.file);
  out += "</Collection>\n</VTKFile>\n";
  write_file_atomically(path, out);
}

}  // namespace mrsph
