// The page a user opens after `isoform pipeline`: NAME-report.html in the
// output folder, with the figures of each step and the pictures Blender
// made (or a note saying why there are none).
#pragma once

#include <string>
#include <vector>

#include "report.h"

namespace isoform::cli {

struct PipelinePage {
  std::string title;                 // "phantom 128^3" or the input's file name
  std::vector<std::pair<std::string, std::string>> rows;  // step, what it gave
  std::vector<std::pair<std::string, std::string>> pictures;  // file in the folder, caption
  std::string pictures_note;         // "" when the pictures were made
  std::vector<std::string> files;    // files to link, relative to the page's folder
};

// Writes the page to path (through a temporary file and a rename).
void write_pipeline_page(const std::string& path, const PipelinePage& page);

}  // namespace isoform::cli
