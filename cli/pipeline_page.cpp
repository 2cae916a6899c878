#include "pipeline_page.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "cli.h"

namespace isoform::cli {
namespace {

std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

}  // namespace

void write_pipeline_page(const std::string& path, const PipelinePage& page) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary);
    out << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>isoform: " << escaped(page.title)
        << "</title>\n<style>body{font-family:sans-serif;max-width:70em;margin:2em auto;}"
           "td,th{padding:0.2em 1em;text-align:left;}figure{display:inline-block;margin:0.5em;}"
           "img{max-width:30em;border:1px solid #ccc;}</style></head><body>\n";
    out << "<h1>isoform pipeline: " << escaped(page.title) << "</h1>\n<table>\n";
    for (const auto& [step, what] : page.rows)
      out << "<tr><th>" << escaped(step) << "</th><td>" << escaped(what) << "</td></tr>\n";
    out << "</table>\n<h2>Pictures</h2>\n";
    if (!page.pictures_note.empty()) out << "<p>" << escaped(page.pictures_note) << "</p>\n";
    for (const auto& [file, caption] : page.pictures)
      out << "<figure><img src=\"" << escaped(file) << "\" alt=\"" << escaped(caption) << "\"><figcaption>"
          << escaped(caption) << "</figcaption></figure>\n";
    out << "<h2>Files</h2>\n<ul>\n";
    for (const std::string& f : page.files)
      out << "<li><a href=\"" << escaped(f) << "\">" << escaped(f) << "</a></li>\n";
    out << "</ul>\n</body></html>\n";
    if (!out) throw Failure(path + ": cannot write the report page");
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    std::remove(temporary.c_str());
    throw Failure(path + ": cannot write the report page (" + ec.message() + ")");
  }
}

}  // namespace isoform::cli
