#pragma once
// Helpers for tests that read a run's outputs back: the d3plot collection, its states (with
// VTK's own reader) and the CSV histories.
#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "solver_support.hpp"

namespace mcdyna::test {

/// The .vtu files listed in a .pvd collection, in order.
inline std::vector<std::string> collection(const std::filesystem::path& pvd) {
  const std::string text = read_text(pvd);
  std::vector<std::string> files;
  const std::string key = "file=\"";
  for (auto at = text.find(key); at != std::string::npos; at = text.find(key, at)) {
    at += key.size();
    files.push_back(text.substr(at, text.find('"', at) - at));
  }
  return files;
}

inline vtkSmartPointer<vtkUnstructuredGrid> read_vtu(const std::filesystem::path& p) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(p.string().c_str());
  reader->Update();
  REQUIRE(reader->GetErrorCode() == 0);
  return reader->GetOutput();
}

/// Every CSV row has as many fields as the header, and the file ends with a whole row.
inline void check_csv_whole(const std::filesystem::path& p) {
  const std::string text = read_text(p);
  CHECK_MESSAGE((!text.empty() && text.back() == '\n'), p.string() << " ends mid-row");
  std::ifstream in(p);
  std::string header, line;
  REQUIRE(std::getline(in, header));
  const auto fields = std::count(header.begin(), header.end(), ',');
  int rows = 0;
  while (std::getline(in, line)) {
    CHECK(std::count(line.begin(), line.end(), ',') == fields);
    ++rows;
  }
  CHECK(rows > 0);
}

}  // namespace mcdyna::test
