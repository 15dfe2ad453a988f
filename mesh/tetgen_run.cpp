#include "sinew/mesh/tetgen_run.hpp"

#include "sinew/core/input_error.hpp"

// The Debian library is built with TETLIBRARY: TetGen then reports failures
// by throwing an int instead of calling exit().
#define TETLIBRARY
#include <tetgen.h>

#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <fcntl.h>
#include <stdexcept>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace sinew {
namespace {

// Exit codes of the child process besides 0 (success).
constexpr int kSwitchesRejected = 90;
constexpr int kOtherFailure = 91;
constexpr int kTetgenCodeBase = 100;  ///< 100 + TetGen's own error code

std::string tetgen_failure(int code)
{
    switch (code) {
    case 1: return "out of memory";
    case 2: return "internal error";
    case 3: return "the surface intersects itself";
    case 4: return "a feature of the surface is smaller than TetGen's tolerance";
    case 5: return "two facets of the surface are too close";
    case 10: return "the input is invalid";
    default: return "error";
    }
}

/// The surface as TetGen input: points and one triangular facet per element.
/// tetgenio frees these arrays with delete[] when it is destroyed.
void fill_input(const Mesh& surface, tetgenio& in)
{
    in.firstnumber = 0;
    in.numberofpoints = surface.num_nodes();
    in.pointlist = new REAL[3 * surface.num_nodes()];
    for (int i = 0; i < surface.num_nodes(); ++i)
        for (int k = 0; k < 3; ++k)
            in.pointlist[3 * i + k] = surface.nodes(k, i);
    in.numberoffacets = surface.num_elements();
    in.facetlist = new tetgenio::facet[surface.num_elements()];
    for (int e = 0; e < surface.num_elements(); ++e) {
        tetgenio::facet& facet = in.facetlist[e];
        tetgenio::init(&facet);
        facet.numberofpolygons = 1;
        facet.polygonlist = new tetgenio::polygon[1];
        tetgenio::polygon& polygon = facet.polygonlist[0];
        tetgenio::init(&polygon);
        polygon.numberofvertices = 3;
        polygon.vertexlist = new int[3];
        for (int k = 0; k < 3; ++k)
            polygon.vertexlist[k] = surface.elements(k, e);
    }
}

bool write_all(int fd, const void* data, std::size_t bytes)
{
    const char* next = static_cast<const char*>(data);
    while (bytes > 0) {
        const ssize_t written = ::write(fd, next, bytes);
        if (written < 0 && errno == EINTR)
            continue;
        if (written <= 0)
            return false;
        next += written;
        bytes -= static_cast<std::size_t>(written);
    }
    return true;
}

/// Message layout: three int32 counts (points, tets, faces), then the point
/// coordinates (double), the tets' and the faces' corners (int32, 0-based).
bool write_output(int fd, const tetgenio& out)
{
    const std::int32_t counts[3] = {out.numberofpoints, out.numberoftetrahedra, out.numberoftrifaces};
    std::vector<std::int32_t> tets(4 * static_cast<std::size_t>(out.numberoftetrahedra));
    for (int t = 0; t < out.numberoftetrahedra; ++t)
        for (int n = 0; n < 4; ++n)
            tets[4 * t + n] = out.tetrahedronlist[out.numberofcorners * t + n] - out.firstnumber;
    std::vector<std::int32_t> faces(3 * static_cast<std::size_t>(out.numberoftrifaces));
    for (std::size_t i = 0; i < faces.size(); ++i)
        faces[i] = out.trifacelist[i] - out.firstnumber;
    return write_all(fd, counts, sizeof counts) &&
           write_all(fd, out.pointlist, sizeof(REAL) * 3 * static_cast<std::size_t>(out.numberofpoints)) &&
           write_all(fd, tets.data(), sizeof(std::int32_t) * tets.size()) &&
           write_all(fd, faces.data(), sizeof(std::int32_t) * faces.size());
}

/// The child: silence TetGen, run it, send the output, exit without running
/// any of the parent's exit handlers.
[[noreturn]] void run_child(const Mesh& surface, const std::string& switches, int fd)
{
    const int null = ::open("/dev/null", O_WRONLY);
    if (null >= 0) {
        ::dup2(null, STDOUT_FILENO);
        ::dup2(null, STDERR_FILENO);
    }
    int status = kOtherFailure;
    try {
        tetgenio in;
        tetgenio out;
        fill_input(surface, in);
        tetgenbehavior behavior;
        std::vector<char> text(switches.begin(), switches.end());
        text.push_back('\0');
        if (!behavior.parse_commandline(text.data())) {
            status = kSwitchesRejected;
        } else {
            tetrahedralize(&behavior, &in, &out);
            status = write_output(fd, out) ? 0 : kOtherFailure;
        }
    } catch (int code) {
        status = kTetgenCodeBase + code;
    } catch (...) {
        status = kOtherFailure;
    }
    ::_exit(status);
}

std::vector<char> read_all(int fd)
{
    std::vector<char> bytes;
    char buffer[1 << 16];
    for (;;) {
        const ssize_t got = ::read(fd, buffer, sizeof buffer);
        if (got < 0 && errno == EINTR)
            continue;
        if (got <= 0)
            return bytes;
        bytes.insert(bytes.end(), buffer, buffer + got);
    }
}

TetgenOutput parse_output(const std::vector<char>& bytes, const std::string& source)
{
    const auto fail = [&] { throw std::runtime_error(source + ": TetGen's output could not be read back"); };
    std::size_t at = 0;
    const auto take = [&](void* into, std::size_t size) {
        if (size == 0)
            return;
        if (at + size > bytes.size())
            fail();
        std::memcpy(into, bytes.data() + at, size);
        at += size;
    };
    std::int32_t counts[3];
    take(counts, sizeof counts);
    if (counts[0] < 0 || counts[1] < 0 || counts[2] < 0)
        fail();
    TetgenOutput output;
    output.points.resize(3, counts[0]);
    take(output.points.data(), sizeof(double) * 3 * static_cast<std::size_t>(counts[0]));
    Eigen::Matrix<std::int32_t, Eigen::Dynamic, Eigen::Dynamic> tets(4, counts[1]);
    take(tets.data(), sizeof(std::int32_t) * 4 * static_cast<std::size_t>(counts[1]));
    Eigen::Matrix<std::int32_t, Eigen::Dynamic, Eigen::Dynamic> faces(3, counts[2]);
    take(faces.data(), sizeof(std::int32_t) * 3 * static_cast<std::size_t>(counts[2]));
    if (at != bytes.size())
        fail();
    output.tetrahedra = tets.cast<int>();
    output.faces = faces.cast<int>();
    return output;
}

} // namespace

TetgenOutput run_tetgen(const Mesh& surface, const std::string& switches, const std::string& source)
{
    int pipe_ends[2];
    if (::pipe(pipe_ends) != 0)
        throw std::runtime_error(source + ": cannot start TetGen (pipe: " + std::strerror(errno) + ")");
    const pid_t parent = ::getpid();
    const pid_t child = ::fork();
    if (child < 0) {
        ::close(pipe_ends[0]);
        ::close(pipe_ends[1]);
        throw std::runtime_error(source + ": cannot start TetGen (fork: " + std::strerror(errno) + ")");
    }
    if (child == 0) {
        // The child dies with sinew: killed or stopped, sinew takes TetGen along.
        if (::prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || ::getppid() != parent)
            ::_exit(kOtherFailure);
        ::close(pipe_ends[0]);
        run_child(surface, switches, pipe_ends[1]);
    }
    ::close(pipe_ends[1]);
    const std::vector<char> bytes = read_all(pipe_ends[0]);
    ::close(pipe_ends[0]);
    int status = 0;
    pid_t waited = 0;
    do
        waited = ::waitpid(child, &status, 0);
    while (waited < 0 && errno == EINTR);
    if (waited < 0)
        throw std::runtime_error(source + ": lost the TetGen process (waitpid: " + std::strerror(errno) + ")");

    if (WIFSIGNALED(status))
        throw InputError(source + ": TetGen failed: it stopped on an error in the surface (its process died with "
                                  "signal " +
                         std::to_string(WTERMSIG(status)) +
                         "); likely causes are features smaller than TetGen's tolerance or nearly touching facets");
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : kOtherFailure;
    if (code == kSwitchesRejected)
        throw InputError(source + ": TetGen rejected the switches '" + switches + "'");
    if (code >= kTetgenCodeBase)
        throw InputError(source + ": TetGen failed: " + tetgen_failure(code - kTetgenCodeBase) + " (TetGen code " +
                         std::to_string(code - kTetgenCodeBase) + ")");
    if (code != 0)
        throw InputError(source + ": TetGen failed (its process exited with status " + std::to_string(code) + ")");
    return parse_output(bytes, source);
}

} // namespace sinew
