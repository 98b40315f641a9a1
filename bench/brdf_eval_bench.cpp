// The C++ side of bench/python_eval.py: seconds per eval() loop over the same direction pairs, one thread,
// for every fit of a material and for measured data. The pairs are N rows Lx,Ly,Lz,Vx,Vy,Vz of float64 in a
// raw file (unit vectors: the loop is the library's, without the Python module's normalising).
#include "bench/timing.h"
#include "materials/models/brdf.h"
#include "materials/params/material_file.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <vector>

int main(int argc, char** argv) {
  using namespace glossy;
  CLI::App app{"Median seconds of one eval() loop over the pairs, per fit (python_eval.py compares)"};
  std::string pairsPath, materialPath, measuredPath;
  int runs = 5;
  app.add_option("--pairs", pairsPath, "raw float64 rows Lx,Ly,Lz,Vx,Vy,Vz")->required();
  app.add_option("--material", materialPath, "material file: each of its fits")->required();
  app.add_option("--measured", measuredPath, "MERL table too");
  app.add_option("--runs", runs, "timed loops per BRDF (median)");
  CLI11_PARSE(app, argc, argv);

  std::ifstream in(pairsPath, std::ios::binary | std::ios::ate);
  const size_t n = size_t(in.tellg()) / (6 * sizeof(double));
  std::vector<Vec3> L(n), V(n);
  in.seekg(0);
  for (size_t i = 0; i < n; ++i) {
    double row[6];
    in.read(reinterpret_cast<char*>(row), sizeof row);
    L[i] = {row[0], row[1], row[2]};
    V[i] = {row[3], row[4], row[5]};
  }
  std::vector<std::pair<std::string, Brdf>> brdfs;
  const MaterialFile material = loadMaterialFile(materialPath);
  for (const Fit& f : material.fits) brdfs.emplace_back(f.id.str(), makeBrdf(f));
  if (!measuredPath.empty()) brdfs.emplace_back("measured", Measured{std::make_shared<const MerlTable>(MerlTable::load(measuredPath))});

  std::vector<Rgb> out(n);
  for (const auto& [name, brdf] : brdfs) {
    const double s = bench::medianSeconds(runs, [&] {
      for (size_t i = 0; i < n; ++i) out[i] = eval(brdf, L[i], V[i]);
    });
    double checksum = 0.0;
    for (const Rgb& c : out) checksum += c.r + c.g + c.b;
    std::printf("%s,%.9f,%.17g\n", name.c_str(), s, checksum);
  }
}
