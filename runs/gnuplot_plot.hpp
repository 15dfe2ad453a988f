#pragma once
#include <string>
#include <vector>

namespace sinew {

/// One curve: its legend title and its points.
struct PlotSeries {
    std::string title;
    std::vector<double> x, y;
};

/// A 2D line plot, drawn by gnuplot (Debian's gnuplot-nox, installed by
/// scripts/setup.sh) with its cairo terminals. Points with y ≤ 0 are left out
/// of a log-scale y axis (gnuplot cannot place them); the data file keeps them.
struct Plot {
    std::string title, x_label, y_label;
    bool log_x = false, log_y = false;
    bool steps = false;  ///< a step function (performance profiles), else lines with points
    std::vector<PlotSeries> series;
};

/// True when a gnuplot with the pngcairo and svg terminals can be run.
bool gnuplot_available();

/// The one-line reason plots cannot be drawn here, for an InputError.
std::string gnuplot_missing_message();

/// Writes `<stem>.dat` (one block per series, "# title" above it, blocks
/// separated by two blank lines, numbers with 17 significant digits),
/// `<stem>.gp` (the script), and runs gnuplot on it for `<stem>.png` and
/// `<stem>.svg` in `folder`. InputError naming the file when gnuplot fails.
void draw_plot(const Plot& plot, const std::string& folder, const std::string& stem);

/// Removes `<stem>.dat`, `.gp`, `.png` and `.svg` from `folder` where they exist.
void remove_plot(const std::string& folder, const std::string& stem);

/// The series of a data file written by draw_plot, for tests and tools that
/// read the plotted data back.
std::vector<PlotSeries> read_plot_data(const std::string& path);

} // namespace sinew
