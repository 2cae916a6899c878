// The comparison study's pictures are made by programs the CLI runs as
// child processes (the library never does): matplotlib plots by
// /usr/bin/python3 and renders by Blender headless, from scripts in
// cli/study/. Missing programs or scripts skip the pictures, never the study.
#pragma once

#include <string>
#include <vector>

namespace isoform::cli {

// The folder holding plot_study.py and render_study.py: $ISOFORM_STUDY_SCRIPTS
// when set, else the source folder compiled in.
std::string study_scripts_folder();

// The first executable among candidates (absolute paths, or names searched
// on PATH), or "" when none is found.
std::string find_program(const std::vector<std::string>& candidates);

// Runs argv[0] with argv (no shell), its output to log_path (appended; ""
// discards it), and returns its exit status (-1 if it could not be started
// or was killed by a signal).
int run_program(const std::vector<std::string>& argv, const std::string& log_path);

}  // namespace isoform::cli
