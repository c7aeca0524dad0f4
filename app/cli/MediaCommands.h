// particlelab-cli record and report: a clip of an experiment in simulated time, and its lab report,
// both drawn without a display (Qt's offscreen platform).
#pragma once

#include "media/ClipFormat.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pl::cli {

struct RecordOptions {
    std::string preset;            // built-in name, preset file or snapshot
    std::vector<std::string> sets; // "key=value"
    std::optional<std::uint64_t> seed;
    std::string out;              // .mp4, .webm or .gif
    double seconds = 10.0;        // length of the clip [s of playback]
    int fps = 30;                 // [frames/s]
    long long stepsPerFrame = 10; // model steps between two frames: the app's pace (5 a frame at 60 frames/s)
    std::string size = "1280x720";
    std::string plot; // a plot of the scene beside it ("energyPlot"); empty: the scene alone
    bool noCaptions = false;
    int threads = 0;
    std::string backend = "auto";
    bool quiet = false;
};

// Why the options cannot make a clip, in one sentence (empty when they can), and the clip's format, size
// and frame count (RecordOptions.cpp).
std::string recordOptionsRefusal(const RecordOptions& options, ClipFormat& format, int& width, int& height,
                                 long long& frames);

// Frames: the state before the first step, then after every stepsPerFrame steps, seconds × fps of them.
// A signal, a model that fails or a file that cannot take more ends the clip where it is, finished.
int recordClip(const RecordOptions& options);

struct ReportOptions {
    std::string preset; // built-in name, preset file or snapshot
    std::vector<std::string> sets;
    std::optional<std::uint64_t> seed;
    std::string out;                // .pdf or .html
    std::string dataDir;            // a folder for the plots' CSV files (made if missing); empty: none
    std::optional<long long> steps; // default: the preset's run length, else 1000
    int threads = 0;
    std::string backend = "auto";
};

// Runs the experiment for its steps, sampling the plots as the app does, then writes the report.
int writeReport(const ReportOptions& options);

} // namespace pl::cli
