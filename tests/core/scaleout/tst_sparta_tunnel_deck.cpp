// The wind tunnel as a 2D SPARTA deck against SPARTA's documented input syntax (create_box, create_grid,
// fix emit/face, read_surf, surf_collide diffuse, bound_modify, compute grid / surf, stats_style), the
// bodies file against the geometry of the bodies, and, where a spa_serial binary is at hand, SPARTA
// itself running the tunnel-cylinder deck.
#include "DeckText.h"
#include "catalog/ModelCatalog.h"
#include "common/AtomicFile.h"
#include "scaleout/LogAndDump.h"
#include "scaleout/SpartaDeck.h"
#include "scaleout/SpartaImport.h"

#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>
#include <algorithm>
#include <array>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>

using namespace pl;
using namespace pl::deck_text;

namespace {

std::unique_ptr<TunnelModel> tunnelFor(const std::string& name,
                                       const std::map<std::string, ParamValue>& sets = {},
                                       const std::vector<Obstacle>& extraBodies = {}) {
    Preset preset = loadPreset(name);
    for (const auto& [key, value] : sets) preset.params[key] = value;
    for (const auto& body : extraBodies) preset.obstacles.push_back(body);
    auto tunnel = std::make_unique<TunnelModel>();
    tunnel->reset(preset);
    return tunnel;
}

// The commands of an input script by name; commands that name an ID (fix, compute, surf_collide, …) by
// name and ID. The last line of each wins.
std::map<std::string, std::vector<std::string>> commandsOf(const std::string& input) {
    static const std::vector<std::string> withId{"fix",          "compute", "surf_collide",
                                                 "bound_modify", "dump",    "dump_modify"};
    std::map<std::string, std::vector<std::string>> seen;
    for (const auto& line : lines(input)) {
        const auto w = words(line);
        if (w.empty() || w[0][0] == '#') continue;
        const bool keyed = std::find(withId.begin(), withId.end(), w[0]) != withId.end() && w.size() > 1;
        seen[keyed ? w[0] + " " + w[1] : w[0]] = w;
    }
    return seen;
}

struct SurfaceFile {
    std::vector<std::array<double, 2>> points;
    std::vector<std::array<std::size_t, 2>> lines; // 0-based point indices p1, p2
};

// read_surf's format A: title, "N points", "M lines", then the Points and Lines sections.
SurfaceFile parseSurface(const std::string& text) {
    SurfaceFile surf;
    std::size_t points = 0, segments = 0;
    std::string section;
    const auto all = lines(text);
    for (std::size_t k = 1; k < all.size(); ++k) {
        const auto w = words(all[k]);
        if (w.empty()) continue;
        if (w.size() == 2 && w[1] == "points")
            points = std::stoul(w[0]);
        else if (w.size() == 2 && w[1] == "lines")
            segments = std::stoul(w[0]);
        else if (w.size() == 1)
            section = w[0];
        else if (section == "Points" && w.size() == 3)
            surf.points.push_back({std::stod(w[1]), std::stod(w[2])});
        else if (section == "Lines" && w.size() == 3)
            surf.lines.push_back({std::stoul(w[1]) - 1, std::stoul(w[2]) - 1});
    }
    if (surf.points.size() != points || surf.lines.size() != segments) qFatal("surface file counts differ");
    return surf;
}

std::string spartaBinary() {
    const QByteArray fromEnvironment = qgetenv("PARTICLELAB_SPARTA");
    if (!fromEnvironment.isEmpty()) return fromEnvironment.toStdString();
    return QStandardPaths::findExecutable("spa_serial").toStdString();
}
} // namespace

class TestSpartaTunnelDeck : public QObject {
    Q_OBJECT
private slots:
    // tunnel-cylinder as SPARTA reads it: the 2D box, grid, weight, free stream, sides and body of the
    // preset, every command with the argument count of SPARTA's documentation. The sides are set here:
    // the stream enters at the left and the top, leaves at the right, the bottom is the symmetry plane.
    void tunnelDeckMatchesTheCylinder() {
        const auto tunnel = tunnelFor("tunnel-cylinder", {{"left", std::string("inflow")},
                                                          {"right", std::string("outflow")},
                                                          {"bottom", std::string("specular")},
                                                          {"top", std::string("inflow")}});
        const TunnelParams& p = tunnel->parameters();
        const auto deck = scaleout::spartaDeck(*tunnel, {1000, 50});
        const std::string& input = file(deck, scaleout::kSpartaInput);
        const std::map<std::string, std::pair<std::size_t, std::size_t>> arity{{"seed", {1, 1}},
                                                                               {"units", {1, 1}},
                                                                               {"dimension", {1, 1}},
                                                                               {"boundary", {3, 3}},
                                                                               {"create_box", {6, 6}},
                                                                               {"create_grid", {3, 3}},
                                                                               {"global", {2, 8}},
                                                                               {"species", {2, 2}},
                                                                               {"mixture", {2, 10}},
                                                                               {"collide", {3, 3}},
                                                                               {"collide_modify", {2, 2}},
                                                                               {"read_surf", {1, 2}},
                                                                               {"surf_collide", {2, 7}},
                                                                               {"surf_modify", {3, 3}},
                                                                               {"bound_modify", {3, 3}},
                                                                               {"create_particles", {3, 3}},
                                                                               {"fix", {4, 12}},
                                                                               {"timestep", {1, 1}},
                                                                               {"compute", {4, 12}},
                                                                               {"dump", {5, 20}},
                                                                               {"dump_modify", {4, 4}},
                                                                               {"stats", {1, 1}},
                                                                               {"stats_style", {1, 20}},
                                                                               {"stats_modify", {3, 3}},
                                                                               {"run", {1, 1}}};
        for (const auto& line : lines(input)) {
            const auto w = words(line);
            if (w.empty() || w[0][0] == '#') continue;
            const auto it = arity.find(w[0]);
            QVERIFY2(it != arity.end(), line.c_str());
            QVERIFY2(w.size() - 1 >= it->second.first && w.size() - 1 <= it->second.second, line.c_str());
        }
        auto c = commandsOf(input);
        QCOMPARE(c["dimension"][1], std::string("2"));
        // inflow and outflow sides are SPARTA's o (emit/face feeds the inflow ones), the specular bottom r.
        QCOMPARE(c["boundary"], (std::vector<std::string>{"boundary", "o", "ro", "p"}));
        QCOMPARE(c["create_box"],
                 (std::vector<std::string>{"create_box", "0", "0.2", "0", "0.12", "-0.5", "0.5"}));
        QCOMPARE(c["create_grid"], (std::vector<std::string>{"create_grid", "100", "60", "1"}));
        QCOMPARE(std::stod(c["global"][2]), p.streamDensity);
        QCOMPARE(std::stod(c["global"][4]), p.fn);
        QCOMPARE(std::stod(c["timestep"][1]), p.dt);
        QCOMPARE(c["mixture"], (std::vector<std::string>{"mixture", "stream", "gas", "vstream", "2634", "0",
                                                         "0", "temp", "200"}));
        QCOMPARE(c["collide"], (std::vector<std::string>{"collide", "vss", "stream", "gas.vss"}));
        QCOMPARE(c["fix inflow"],
                 (std::vector<std::string>{"fix", "inflow", "emit/face", "stream", "xlo", "yhi"}));
        // The half cylinder on the symmetry plane reaches below the box: clipped, diffuse at 500 K.
        QCOMPARE(c["read_surf"], (std::vector<std::string>{"read_surf", scaleout::kSpartaBodies, "clip"}));
        QCOMPARE(c["surf_collide body"],
                 (std::vector<std::string>{"surf_collide", "body", "diffuse", "500", "1.0"}));
        QCOMPARE(c["create_particles"], (std::vector<std::string>{"create_particles", "stream", "n", "0"}));
        // Fields over the window from sample_start (800) to the end; forces over each stats interval.
        QCOMPARE(c["fix fields"][4], std::string("1"));
        QCOMPARE(c["fix fields"][5], std::string("200"));
        QCOMPARE(c["fix fields"][6], std::string("1000"));
        QCOMPARE(c["dump fields"][4], std::string("1000"));
        QCOMPARE(c["dump fields"][5], std::string(scaleout::kSpartaGrid));
        QCOMPARE(c["fix surfaceForce"][5], std::string("50"));
        QCOMPARE(c["stats"][1], std::string("50"));
        QCOMPARE(c["stats_style"].back(), std::string("c_force[2]"));
        QCOMPARE(c["run"][1], std::string("1000"));
        QVERIFY(input.find("bound_modify") == std::string::npos); // no diffuse side
        std::vector<std::string> vss;
        for (const auto& l : lines(file(deck, "gas.vss")))
            if (!l.empty() && l[0] != '#') vss = words(l);
        QCOMPARE(vss, (std::vector<std::string>{"gas", "4.17e-10", "0.81", "273", "1"}));
    }

    // The bodies file: the disc as a closed polygon with its vertices on the circle, segments below a
    // quarter cell, each outward normal ẑ × (p2 − p1) pointing away from the body, and the area an
    // inscribed N-gon has, (N/2) r² sin(2π/N); a box as its four corners, clockwise.
    void bodiesAreOutwardFacingPolygons() {
        Obstacle box;
        box.shape = Obstacle::Shape::Box;
        box.x = 0.15, box.y = 0.06, box.halfWidth = 0.004, box.halfHeight = 0.01;
        const auto tunnel = tunnelFor("tunnel-cylinder", {}, {box});
        const auto deck = scaleout::spartaDeck(*tunnel, {1000, 50});
        const SurfaceFile surf = parseSurface(file(deck, scaleout::kSpartaBodies));
        const Obstacle& disc = tunnel->obstacles()[0];
        const auto sides =
            static_cast<std::size_t>(scaleout::discPolygonSides(disc.radius, tunnel->parameters()));
        QVERIFY(sides >= 64);
        QCOMPARE(surf.points.size(), sides + 4);
        QCOMPARE(surf.lines.size(), sides + 4);
        std::vector<int> uses(surf.points.size(), 0);
        double signedArea = 0.0, longest = 0.0;
        for (std::size_t k = 0; k < surf.lines.size(); ++k) {
            const auto [a, b] = surf.lines[k];
            ++uses[a], ++uses[b];
            const Obstacle& body = k < sides ? disc : box;
            const auto &p1 = surf.points[a], &p2 = surf.points[b];
            const double nx = -(p2[1] - p1[1]), ny = p2[0] - p1[0]; // ẑ × (p2 − p1)
            const double mx = 0.5 * (p1[0] + p2[0]) - body.x, my = 0.5 * (p1[1] + p2[1]) - body.y;
            QVERIFY2(nx * mx + ny * my > 0, "a normal points into the body");
            if (k < sides) {
                QVERIFY(std::abs(std::hypot(p1[0] - disc.x, p1[1] - disc.y) - disc.radius) <
                        1e-12 * disc.radius);
                signedArea +=
                    0.5 * ((p1[0] - disc.x) * (p2[1] - disc.y) - (p2[0] - disc.x) * (p1[1] - disc.y));
                longest = std::max(longest, std::hypot(p2[0] - p1[0], p2[1] - p1[1]));
            } else {
                QVERIFY(std::abs(std::abs(p1[0] - box.x) - box.halfWidth) < 1e-15);
                QVERIFY(std::abs(std::abs(p1[1] - box.y) - box.halfHeight) < 1e-15);
            }
        }
        for (int u : uses) QCOMPARE(u, 2); // watertight: every point ends two segments
        const double n = static_cast<double>(sides);
        const double inscribed = 0.5 * n * disc.radius * disc.radius * std::sin(2 * std::numbers::pi / n);
        QVERIFY(std::abs(-signedArea - inscribed) < 1e-12 * inscribed); // clockwise: negative signed area
        QVERIFY(longest <=
                0.25 * std::min(tunnel->parameters().cellWidth(), tunnel->parameters().cellHeight()));
    }

    // tunnel-couette: periodic along the walls, diffuse walls at 273 K moving at ∓250 m/s, the gas
    // created at rest, no inflow and no bodies.
    void couetteWallsAreMovingDiffuseSides() {
        const auto tunnel = tunnelFor("tunnel-couette");
        const auto deck = scaleout::spartaDeck(*tunnel, {4000, 100});
        const std::string& input = file(deck, scaleout::kSpartaInput);
        auto c = commandsOf(input);
        QCOMPARE(c["boundary"], (std::vector<std::string>{"boundary", "p", "s", "p"}));
        QCOMPARE(c["surf_collide wall_ylo"],
                 (std::vector<std::string>{"surf_collide", "wall_ylo", "diffuse", "273", "1.0", "translate",
                                           "-250", "0", "0"}));
        QCOMPARE(c["surf_collide wall_yhi"],
                 (std::vector<std::string>{"surf_collide", "wall_yhi", "diffuse", "273", "1.0", "translate",
                                           "250", "0", "0"}));
        QCOMPARE(c["bound_modify ylo"],
                 (std::vector<std::string>{"bound_modify", "ylo", "collide", "wall_ylo"}));
        QCOMPARE(c["bound_modify yhi"],
                 (std::vector<std::string>{"bound_modify", "yhi", "collide", "wall_yhi"}));
        QCOMPARE(c["create_particles"], (std::vector<std::string>{"create_particles", "rest", "n", "0"}));
        QCOMPARE(c["mixture"], (std::vector<std::string>{"mixture", "rest", "vstream", "0", "0", "0"}));
        QVERIFY(!c.contains("fix inflow"));
        QVERIFY(!c.contains("read_surf"));
        QVERIFY(!c.contains("compute surfaceForce"));
        QVERIFY(c["stats_style"].back() != "c_force[2]");
        for (const auto& f : deck.files) QVERIFY(f.name != scaleout::kSpartaBodies);
    }

    void tunnelScenesSpartaCannotRunAreRefused() {
        QVERIFY_THROWS_EXCEPTION(scaleout::ExportError,
                                 scaleout::spartaDeck(*tunnelFor("tunnel-shock-tube"), {1800, 1}));
        const auto cylinder = tunnelFor("tunnel-cylinder");
        QVERIFY_THROWS_EXCEPTION(scaleout::ExportError,
                                 scaleout::spartaDeck(*cylinder, {800, 1})); // no window
        // 1000 steps are no whole number of 300-step force rows; the empty Couette channel has no forces.
        QVERIFY_THROWS_EXCEPTION(scaleout::ExportError, scaleout::spartaDeck(*cylinder, {1000, 300}));
        QCOMPARE(commandsOf(file(scaleout::spartaDeck(*tunnelFor("tunnel-couette"), {4000, 300}),
                                 scaleout::kSpartaInput))["run"][1],
                 std::string("4000"));
        QCOMPARE(commandsOf(file(scaleout::spartaDeck(*cylinder, {801, 1}),
                                 scaleout::kSpartaInput))["fix fields"][5],
                 std::string("1"));
    }

    // SPARTA itself runs the deck: its initial particle count is ours in expectation, the gas at the
    // inflow has the free stream's density, and the half cylinder feels a drag. Skipped without SPARTA.
    void spartaRunsTheTunnelDeck() {
        const std::string binary = spartaBinary();
        if (binary.empty())
            QSKIP("no SPARTA: put spa_serial on PATH or set PARTICLELAB_SPARTA (build it from "
                  "https://github.com/sparta/sparta: cd src && make serial)");
        QTemporaryDir dir;
        const std::string folder = dir.path().toStdString();
        const auto tunnel = tunnelFor("tunnel-cylinder", {{"sample_start", 20.0}});
        const TunnelParams& p = tunnel->parameters();
        const auto deck = scaleout::spartaDeck(*tunnel, {40, 10});
        for (const auto& f : deck.files) writeFileAtomically(folder + "/" + f.name, f.content);
        QProcess sparta;
        sparta.setWorkingDirectory(dir.path());
        sparta.start(QString::fromStdString(binary),
                     {"-in", scaleout::kSpartaInput, "-echo", "none", "-screen", "none"});
        QVERIFY(sparta.waitForFinished(60000));
        std::ifstream logFile(folder + "/" + scaleout::kSpartaLog);
        std::stringstream log;
        log << logFile.rdbuf();
        QVERIFY2(sparta.exitStatus() == QProcess::NormalExit && sparta.exitCode() == 0, log.str().c_str());
        std::istringstream logText(log.str());
        const auto stats = scaleout::readThermo(logText);
        QCOMPARE(stats.rows.size(), std::size_t(5)); // steps 0, 10, …, 40
        // Both codes fill the open area with n (W H − π r²/2) / F_N particles in expectation; each count
        // is a sum of per-cell draws at most as broad as Poisson's, so 5 √N bounds both.
        const double radius = tunnel->obstacles()[0].radius;
        const double expected =
            p.streamDensity * (p.boxWidth * p.boxHeight - 0.5 * std::numbers::pi * radius * radius) / p.fn;
        const double theirs = stats.rows[0][static_cast<std::size_t>(stats.column("Np"))];
        const double ours = static_cast<double>(tunnel->state().size());
        QVERIFY2(std::abs(theirs - expected) < 5 * std::sqrt(expected), std::to_string(theirs).c_str());
        QVERIFY2(std::abs(ours - expected) < 5 * std::sqrt(expected), std::to_string(ours).c_str());
        // Drag per unit depth of the half cylinder over steps 31–40: positive and below a stagnation
        // momentum flux ρU² over twice its projected height r (C_D < 4).
        const double drag = stats.rows.back()[static_cast<std::size_t>(stats.column("c_force[1]"))];
        const double bound = 4.0 * 0.5 * p.streamDensity * p.mass() * p.streamSpeed * p.streamSpeed * radius;
        QVERIFY2(drag > 0 && drag < bound, std::to_string(drag).c_str());

        // The grid fields: one row per cell (split cells add rows); in the first 10 columns, ahead of the
        // shock, the window's density is the free stream's. About 8 particles per cell and step there:
        // treating the 20 sampled steps as one (they are correlated), 5/√N of those cells bounds it.
        std::ifstream grid(folder + "/" + scaleout::kSpartaGrid);
        std::string line, header;
        std::size_t cells = 0;
        double inflowDensity = 0.0, inflowCells = 0.0;
        while (std::getline(grid, line)) { // the last snapshot (step 40) counts
            if (line.rfind("ITEM:", 0) == 0) {
                header = line.rfind("ITEM: CELLS", 0) == 0 ? line : std::string();
                if (!header.empty()) cells = 0, inflowDensity = inflowCells = 0;
            } else if (!header.empty()) {
                const auto w = words(line); // id xlo ylo xhi yhi vol, then n nrho u v w usq vsq wsq
                QCOMPARE(w.size(), std::size_t(14));
                ++cells;
                if (std::stod(w[3]) <= 10 * p.cellWidth() + 1e-12)
                    inflowDensity += std::stod(w[7]), ++inflowCells;
            }
        }
        QVERIFY(cells >= static_cast<std::size_t>(p.cellsX * p.cellsY));
        QCOMPARE(inflowCells, 10.0 * static_cast<double>(p.cellsY));
        const double perStep = p.streamDensity * 10 * p.cellWidth() * p.boxHeight / p.fn;
        QVERIFY2(std::abs(inflowDensity / inflowCells / p.streamDensity - 1) < 5 / std::sqrt(perStep),
                 std::to_string(inflowDensity / inflowCells).c_str());
    }
};

QTEST_GUILESS_MAIN(TestSpartaTunnelDeck)
#include "tst_sparta_tunnel_deck.moc"
