// The comparison study's files: report.json (everything measured),
// samples.csv (the sample table, one row per lattice sample, every surface
// side by side) and report.md (the table a person reads). Each is written
// atomically; all three are prepared before the first is renamed into place.
#pragma once

#include <string>

#include "compare.h"

namespace isoform::compare {

struct StudyInfo {
  std::string input;        // what the base mesh was ("reduced.ply"), for the texts
  std::string loop_options; // e.g. "isolation 6, boundary edges and corners sharp"
};

std::string report_json(const CompareResult& r, const StudyInfo& info);
std::string samples_csv(const CompareResult& r);
std::string report_markdown(const CompareResult& r, const StudyInfo& info);

// Writes the three files into directory, which must exist. Throws IoError
// naming the directory or file.
void write_report(const CompareResult& r, const StudyInfo& info, const std::string& directory);

}  // namespace isoform::compare
