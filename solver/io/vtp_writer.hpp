// ParaView PolyData (.vtp) snapshots of particle bodies, and a .pvd collection that lists them
// with their times so ParaView opens the series as one animated data set.
#pragma once

#include "core/types.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace mrsph {

struct PointField {
  std::string name;
  int components;              // 1 or 3 (2D vectors are written with z = 0)
  std::vector<double> values;  // size = points * components
};

struct PointCloud {
  Vec2Array points;
  std::vector<PointField> fields;

  void add_scalar(const std::string& name, const RealArray& values);
  void add_vector(const std::string& name, const Vec2Array& values);
};

std::string vtp_document(const PointCloud& cloud);
void write_vtp(const std::filesystem::path& path, const PointCloud& cloud);

struct PvdEntry {
  double time;
  std::string file;  // relative to the .pvd
};
void write_pvd(const std::filesystem::path& path, const std::vector<PvdEntry>& entries);

}  // namespace mrsph
