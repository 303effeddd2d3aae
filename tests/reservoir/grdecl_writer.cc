// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "reservoir/grdecl_writer.h"

#include <cstdio>
#include <sstream>

namespace isovdb::test {

Eigen::Vector3d boxNode(const BoxGrid& g, int i, int j, int k, int columnI) {
  const double x = g.mirrorX ? g.origin.x() - i * g.cell : g.origin.x() + i * g.cell;
  const double shift = (columnI >= g.nx / 2 ? g.faultThrow : 0.0) + (g.pillarShift ? g.pillarShift(i, j) : 0.0);
  double depth = k * (g.layer > 0 ? g.layer : g.cell);
  if (g.thickness) {
    depth = 0;
    for (int layer = 0; layer < k; ++layer) depth += g.thickness(i, j, layer);
  }
  return {x, g.origin.y() + j * g.cell, g.origin.z() + depth + shift};
}

std::string boxGrdecl(const BoxGrid& g, const std::string& name) {
  std::ostringstream out;
  out.precision(12);
  out << "-- synthetic box grid\nSPECGRID\n " << g.nx << ' ' << g.ny << ' ' << g.nz << " 1 F /\n\nCOORD\n";
  for (int j = 0; j <= g.ny; ++j)
    for (int i = 0; i <= g.nx; ++i) {
      const Eigen::Vector3d top = boxNode(g, i, j, 0, 0), bottom = boxNode(g, i, j, g.nz, 0);
      out << top.x() << ' ' << top.y() << ' ' << top.z() << ' ' << bottom.x() << ' ' << bottom.y() << ' ' << bottom.z()
          << '\n';
    }
  out << "/\n\nZCORN\n";
  for (int k = 0; k < g.nz; ++k)
    for (int kz = 0; kz < 2; ++kz)
      for (int j = 0; j < g.ny; ++j)
        for (int jy = 0; jy < 2; ++jy) {
          for (int i = 0; i < g.nx; ++i)
            for (int ix = 0; ix < 2; ++ix) out << boxNode(g, i + ix, j + jy, k + kz, i).z() << ' ';
          out << '\n';
        }
  out << "/\n\nACTNUM\n";
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) out << ((!g.active || g.active(i, j, k)) ? 1 : 0) << ((i + 1) % 20 ? ' ' : '\n');
  out << "/\n\n" << name << '\n';
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const Eigen::Vector3d centre = 0.5 * (boxNode(g, i, j, k, i) + boxNode(g, i + 1, j + 1, k + 1, i));
        out << g.field(centre) << '\n';
      }
  out << "/\n";
  return out.str();
}

}  // namespace isovdb::test
