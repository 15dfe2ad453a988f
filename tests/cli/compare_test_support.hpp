#pragma once
// What the compare tests check in a comparison's folder: plot files and the
// plotted data against the runs' histories.
#include "run_sinew.hpp"

#include "sinew/runs/gnuplot_plot.hpp"

#include <cmath>
#include <map>
#include <string>

namespace sinew::test::compare {

inline bool has_png_signature(const std::string& path)
{
    const std::string bytes = slurp(path);
    return bytes.size() > 8 && bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0;
}

inline bool is_svg(const std::string& path)
{
    const std::string text = slurp(path);
    return text.find("<svg") != std::string::npos && text.find("</svg>") != std::string::npos;
}

/// A JSON number, or NaN for null (compare.json writes non-finite values as null).
inline double value_of(const nlohmann::json& v) { return v.is_null() ? std::nan("") : v.get<double>(); }

inline bool same(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

/// Every run's history column `field` equals the series of the same title in `<stem>.dat`.
inline void check_history_plot(const std::string& folder, const std::string& stem, const nlohmann::json& runs,
                        const std::string& field)
{
    std::map<std::string, sinew::PlotSeries> series;
    for (auto& s : sinew::read_plot_data(folder + "/" + stem + ".dat"))
        series[s.title] = s;
    REQUIRE(series.size() == runs.size());
    for (const auto& run : runs) {
        const auto& history = run["result"]["history"];
        const sinew::PlotSeries& plotted = series.at(run["strategy"].get<std::string>());
        REQUIRE(plotted.x.size() == history.size());
        for (size_t i = 0; i < history.size(); ++i) {
            CHECK(plotted.x[i] == history[i]["iteration"].get<double>());
            CHECK(same(plotted.y[i], value_of(history[i][field])));
        }
    }
}

} // namespace sinew::test::compare
