#include "sinew/runs/gnuplot_plot.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/runs/output_file.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <spawn.h>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace sinew {
namespace {

/// A gnuplot single-quoted string: no escapes inside, a quote doubled.
std::string quoted(const std::string& text)
{
    std::string out = "'";
    for (char c : text)
        out += c == '\'' ? std::string("''") : std::string(1, c);
    return out + "'";
}

bool plottable(const Plot& plot, double x, double y)
{
    return std::isfinite(x) && std::isfinite(y) && (!plot.log_x || x > 0) && (!plot.log_y || y > 0);
}

bool has_points(const Plot& plot, const PlotSeries& series)
{
    for (size_t i = 0; i < series.x.size(); ++i)
        if (plottable(plot, series.x[i], series.y[i]))
            return true;
    return false;
}

std::string data_text(const Plot& plot)
{
    std::ostringstream out;
    bool first = true;
    for (const PlotSeries& series : plot.series) {
        if (series.x.empty())
            continue;
        out << (first ? "" : "\n\n") << "# " << series.title << "\n";
        first = false;
        char line[96];
        for (size_t i = 0; i < series.x.size(); ++i) {
            std::snprintf(line, sizeof line, "%.17g %.17g\n", series.x[i], series.y[i]);
            out << line;
        }
    }
    return out.str();
}

/// Runs `gnuplot script` with its output and errors in `log`; its exit code
/// (−1 when it could not be started).
int run_gnuplot(const std::string& script, const std::string& log)
{
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    std::string program = "gnuplot";
    std::vector<char*> argv = {program.data(), const_cast<char*>(script.c_str()), nullptr};
    pid_t pid = 0;
    const int spawned = posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0)
        return -1;
    int status = 0;
    if (waitpid(pid, &status, 0) < 0 || !WIFEXITED(status))
        return -1;
    return WEXITSTATUS(status);
}

std::string first_line(const std::string& path)
{
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line))
        if (!line.empty())
            return line;
    return "no message";
}

/// The plot command: one curve per series that has a point to draw.
std::string plot_command(const Plot& plot, const std::string& data)
{
    std::string command;
    int block = 0;
    for (const PlotSeries& series : plot.series) {
        if (series.x.empty())
            continue;
        if (has_points(plot, series)) {
            // Points a log axis cannot place become undefined (1/0) and are skipped.
            const std::string x = plot.log_x ? "($1>0?$1:1/0)" : "1";
            const std::string y = plot.log_y ? "($2>0?$2:1/0)" : "2";
            command += std::string(command.empty() ? "plot " : ", \\\n     ") + quoted(data) + " index " +
                       std::to_string(block) + " using " + x + ":" + y +
                       (plot.steps ? " with steps" : " with linespoints") +
                       // gnuplot cycles 8 colours; the next 8 curves are dashed
                       " lw 1.5 dt " + std::to_string(block / 8 + 1) + " title " + quoted(series.title);
        }
        ++block;
    }
    return command;
}

std::string script_text(const Plot& plot, const std::string& data, const std::string& png, const std::string& svg)
{
    bool any = false;
    for (const PlotSeries& series : plot.series)
        any = any || has_points(plot, series);
    std::ostringstream out;
    out << "set terminal pngcairo size 1000,600 noenhanced font ',10'\n"
        << "set output " << quoted(png) << "\n"
        << "set title " << quoted(plot.title) << "\n"
        << "set xlabel " << quoted(plot.x_label) << "\n"
        << "set ylabel " << quoted(plot.y_label) << "\n"
        << "set grid\nset key outside right top\n"
        << (plot.log_x ? "set logscale x\n" : "") << (plot.log_y ? "set logscale y\nset format y '%.0e'\n" : "")
        << (plot.steps ? "set yrange [0:1.05]\n" : "");
    if (any)
        out << plot_command(plot, data) << "\n";
    else
        out << "unset key\nunset logscale\nset label 1 'no data to plot' at graph 0.5, 0.5 center\n"
            << "plot [0:1] [0:1] 1/0 notitle\n";
    out << "set terminal svg size 1000,600 noenhanced font 'sans,10'\n"
        << "set output " << quoted(svg) << "\nreplot\n";
    return out.str();
}

} // namespace

bool gnuplot_available()
{
    const std::filesystem::path folder = std::filesystem::temp_directory_path();
    const std::string script = (folder / ("sinew-gnuplot-probe-" + std::to_string(::getpid()) + ".gp")).string();
    const std::string log = script + ".log";
    {
        std::ofstream out(script);
        out << "set terminal pngcairo\nset terminal svg\n";
    }
    const int code = run_gnuplot(script, log);
    std::remove(script.c_str());
    std::remove(log.c_str());
    return code == 0;
}

std::string gnuplot_missing_message()
{
    return "the plots need gnuplot with its pngcairo and svg terminals (Debian: apt-get install gnuplot-nox, "
           "which scripts/setup.sh does); --no-plots writes the rest";
}

void draw_plot(const Plot& plot, const std::string& folder, const std::string& stem)
{
    const std::filesystem::path base = std::filesystem::absolute(folder) / stem;
    const std::string data = base.string() + ".dat", script = base.string() + ".gp";
    write_text_file(data, data_text(plot));
    write_text_file(script, script_text(plot, data, base.string() + ".png", base.string() + ".svg"));
    const std::string log = base.string() + ".log";
    const int code = run_gnuplot(script, log);
    if (code != 0)
        throw std::runtime_error("gnuplot failed on '" + script + "' (exit " + std::to_string(code) +
                                 "): " + first_line(log));
    std::remove(log.c_str());
}

void remove_plot(const std::string& folder, const std::string& stem)
{
    for (const char* extension : {".dat", ".gp", ".png", ".svg"})
        std::remove((std::filesystem::path(folder) / (stem + extension)).c_str());
}

std::vector<PlotSeries> read_plot_data(const std::string& path)
{
    std::ifstream in(path);
    if (!in)
        throw InputError("cannot read '" + path + "'");
    std::vector<PlotSeries> series;
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("# ", 0) == 0) {
            series.push_back({line.substr(2), {}, {}});
            continue;
        }
        if (line.empty() || series.empty())
            continue;
        // strtod, unlike operator>>, reads the "nan" and "inf" a history may hold.
        char* end = nullptr;
        const double x = std::strtod(line.c_str(), &end);
        char* after = nullptr;
        const double y = std::strtod(end, &after);
        if (end == line.c_str() || after == end || *after != '\0')
            throw InputError(path + ": '" + line + "' is not two numbers");
        series.back().x.push_back(x);
        series.back().y.push_back(y);
    }
    return series;
}

} // namespace sinew
