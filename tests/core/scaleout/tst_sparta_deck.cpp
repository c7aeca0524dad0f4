// The SPARTA deck of the DSMC cell against SPARTA's documented input syntax (species, collide vss,
// read_particles, stats_style, dump particle) and the cross-section mapping against SPARTA's VSS formula.
// The wind tunnel's deck: tst_sparta_tunnel_deck.cpp.
#include "DeckText.h"
#include "catalog/ModelCatalog.h"
#include "common/AtomicFile.h"
#include "scaleout/SpartaDeck.h"
#include "scaleout/SpartaImport.h"

#include <QTemporaryDir>
#include <QtTest>
#include <map>
#include <numbers>
#include <sstream>

using namespace pl;
using namespace pl::deck_text;

namespace {

std::unique_ptr<DsmcModel> cellFor(const std::string& name,
                                   const std::map<std::string, ParamValue>& sets = {}) {
    Preset preset = loadPreset(name);
    for (const auto& [key, value] : sets) preset.params[key] = value;
    auto cell = std::make_unique<DsmcModel>();
    cell->reset(preset);
    return cell;
}

// SPARTA's σ c_r of one species with itself (collide_vss.cpp: prefactor × (c_r²)^(1−ω), m_r = m/2).
double spartaSigmaCr(const scaleout::VssParameters& vss, double mass, double cr) {
    const double prefactor = std::numbers::pi * vss.diameter * vss.diameter *
                             std::pow(2.0 * kBoltzmann * vss.tref / (0.5 * mass), vss.omega - 0.5) /
                             std::tgamma(2.5 - vss.omega);
    return prefactor * std::pow(cr * cr, 1.0 - vss.omega);
}

} // namespace

class TestSpartaDeck : public QObject {
    Q_OBJECT
private slots:
    // Each model's σ c_r through SPARTA's formula equals ours at every relative speed.
    void crossSectionsMapExactly() {
        for (const char* model : {"inverse-root", "hard-sphere", "vhs", "maxwell"}) {
            const auto cell = cellFor("dsmc-write-up", {{"cross_section", std::string(model)}});
            const auto vss = scaleout::vssParameters(cell->parameters(), cell->collisionModel());
            QCOMPARE(vss.alpha, 1.0);
            for (double cr : {10.0, 137.0, 400.0, 2500.0}) {
                const double ours = cell->collisionModel().sigmaCr(cr);
                const double theirs = spartaSigmaCr(vss, cell->parameters().mass(), cr);
                QVERIFY2(std::abs(theirs - ours) <= 1e-12 * ours, model);
            }
        }
        // The write-up's σ = 1e-18 c_r^-½ is VHS with ω = 3/4 and d_ref = 1.1259e-10 m at T_ref = 273 K (O2).
        const auto seed = cellFor("dsmc-write-up");
        const auto vss = scaleout::vssParameters(seed->parameters(), seed->collisionModel());
        QCOMPARE(vss.omega, 0.75);
        QVERIFY(std::abs(vss.diameter - 1.12586e-10) < 1e-15);
    }

    void deckUsesSpartasDocumentedCommands() {
        const auto cell = cellFor("dsmc-write-up");
        const auto deck = scaleout::spartaDeck(*cell, {500, 1});
        // Every command line has the argument count SPARTA's documentation gives it.
        const std::map<std::string, std::pair<std::size_t, std::size_t>> arity{
            {"seed", {1, 1}},     {"units", {1, 1}},          {"dimension", {1, 1}},
            {"boundary", {3, 3}}, {"create_box", {6, 6}},     {"create_grid", {3, 3}},
            {"global", {2, 2}},   {"species", {2, 2}},        {"mixture", {2, 2}},
            {"collide", {3, 3}},  {"collide_modify", {2, 2}}, {"read_particles", {2, 2}},
            {"timestep", {1, 1}}, {"compute", {3, 6}},        {"variable", {3, 3}},
            {"stats", {1, 1}},    {"stats_style", {1, 20}},   {"stats_modify", {3, 3}},
            {"dump", {5, 10}},    {"dump_modify", {4, 4}},    {"run", {1, 1}}};
        std::map<std::string, std::vector<std::string>> seen;
        for (const auto& line : lines(file(deck, scaleout::kSpartaInput))) {
            const auto w = words(line);
            if (w.empty() || w[0][0] == '#') continue;
            const auto it = arity.find(w[0]);
            QVERIFY2(it != arity.end(), line.c_str());
            QVERIFY2(w.size() - 1 >= it->second.first && w.size() - 1 <= it->second.second, line.c_str());
            seen[w[0] + (w[0] == "global" ? " " + w[1] : "")] = w;
        }
        QCOMPARE(seen["units"][1], std::string("si"));
        QCOMPARE(seen["boundary"], (std::vector<std::string>{"boundary", "p", "p", "p"}));
        QCOMPARE(std::stod(seen["global fnum"][2]), 5e8);
        QCOMPARE(std::stod(seen["timestep"][1]), 2e-5);
        QCOMPARE(seen["run"][1], std::string("500"));
        // collide vss MIXTURE FILE over a mixture of the species the species command reads from its file.
        QCOMPARE(seen["collide"][1], std::string("vss"));
        QCOMPARE(seen["collide"][2], seen["mixture"][1]);
        QCOMPARE(seen["mixture"][2], seen["species"][2]);
        const double side = std::stod(seen["create_box"][2]);
        QVERIFY(std::abs(side * side * side - 1e-8) < 1e-22); // the cell's volume
        QCOMPARE(seen["dump"][2], std::string("particle"));
        QCOMPARE(seen["dump"][3], seen["mixture"][1]);

        // Species file: ID and 9 properties; collision file: ID diam omega tref alpha.
        std::vector<std::string> species, vss;
        for (const auto& l : lines(file(deck, seen["species"][1])))
            if (!l.empty() && l[0] != '#') species = words(l);
        for (const auto& l : lines(file(deck, seen["collide"][3])))
            if (!l.empty() && l[0] != '#') vss = words(l);
        QCOMPARE(species.size(), std::size_t(10));
        QCOMPARE(species[0], seen["species"][2]);
        QCOMPARE(std::stod(species[1]), 32.0);
        QCOMPARE(std::stod(species[2]), cell->parameters().mass());
        QCOMPARE(species[3], std::string("0")); // no rotational energy, as our molecules
        QCOMPARE(vss.size(), std::size_t(5));
        QCOMPARE(vss[0], species[0]);
        QCOMPARE(std::stod(vss[2]), 0.75);
    }

    // read_particles wants a dump snapshot with 8 fields per particle: id type x y z vx vy vz, inside the
    // box. The velocities are the cell's, to the last digit.
    void particleFileHoldsTheExactStart() {
        for (const char* preset : {"dsmc-write-up", "dsmc-bkw"}) {
            const auto cell = cellFor(preset);
            const auto deck = scaleout::spartaDeck(*cell, {10, 5});
            const auto text = lines(file(deck, scaleout::kSpartaParticles));
            QCOMPARE(text[0], std::string("ITEM: TIMESTEP"));
            QCOMPARE(text[2], std::string("ITEM: NUMBER OF ATOMS"));
            const std::size_t n = std::stoul(text[3]);
            QCOMPARE(n, cell->state().size());
            QCOMPARE(text[8], std::string("ITEM: ATOMS id type x y z vx vy vz"));
            QCOMPARE(text.size(), 9 + n);
            const double side = std::cbrt(cell->parameters().cellVolume);
            for (std::size_t i = 0; i < n; ++i) {
                const auto w = words(text[9 + i]);
                QCOMPARE(w.size(), std::size_t(8));
                QCOMPARE(std::stoul(w[0]), i + 1);
                for (int c = 2; c < 5; ++c) QVERIFY(std::stod(w[c]) >= 0 && std::stod(w[c]) < side);
                QCOMPARE(std::stod(w[5]), cell->state().vx[i]);
                QCOMPARE(std::stod(w[6]), cell->state().vy[i]);
                QCOMPARE(std::stod(w[7]), cell->state().vz[i]);
            }
        }
    }

    // Our run written as SPARTA's stats and velocity dump and read back gives our series row (all but
    // (σ c_r)_max, which SPARTA does not print) and our histograms, bit for bit.
    void importRoundTripGivesOurObservables() {
        QTemporaryDir dir;
        const std::string folder = dir.path().toStdString();
        auto cell = cellFor("dsmc-bkw", {{"count_a", 3000.0}});
        const auto deck = scaleout::spartaDeck(*cell, {40, 40});
        for (const auto& f : deck.files) writeFileAtomically(folder + "/" + f.name, f.content);
        for (int s = 0; s < 40; ++s) cell->step();
        const auto columns = cell->seriesColumns();
        const std::vector<double> ours = cell->sampleSeries();
        auto at = [&](const char* name) {
            return ours[static_cast<std::size_t>(std::find(columns.begin(), columns.end(), name) -
                                                 columns.begin())];
        };
        std::ostringstream log, dump;
        log.precision(17);
        dump.precision(17);
        const double n = static_cast<double>(cell->state().size());
        log << "Step Time Np Natt Ncoll Ncollave\n0 0 " << n << " 0 0 0\n40 " << at("time") << ' ' << n << ' '
            << at("ng") << ' ' << at("nc") << ' ' << at("collisions_per_particle") * n / 2.0 / 40.0
            << "\nLoop time of 0.1 on 1 procs for 40 steps with 3000 particles\n";
        dump << "ITEM: TIMESTEP\n40\nITEM: NUMBER OF ATOMS\n"
             << cell->state().size()
             << "\nITEM: BOX BOUNDS pp pp pp\n0 1\n0 1\n0 1\nITEM: ATOMS id vx vy vz\n";
        for (std::size_t i = cell->state().size(); i-- > 0;) // any order: the ids say which is which
            dump << i + 1 << ' ' << cell->state().vx[i] << ' ' << cell->state().vy[i] << ' '
                 << cell->state().vz[i] << '\n';
        writeFileAtomically(folder + "/" + scaleout::kSpartaLog, log.str());
        writeFileAtomically(folder + "/" + scaleout::kSpartaDump, dump.str());

        const auto imported = scaleout::importSpartaRun(folder);
        QCOMPARE(imported.frames, 1LL); // the stats row of step 0 has no dump: not a row
        QCOMPARE(imported.series.rows(), std::size_t(1));
        const auto& row = imported.series.row(0);
        for (std::size_t c = 0; c < columns.size(); ++c) {
            if (columns[c] == "sigma_cr_max")
                QVERIFY(std::isnan(row[c]));
            else if (!(std::isnan(ours[c]) && std::isnan(row[c])))
                QVERIFY2(row[c] == ours[c], columns[c].c_str());
        }
        const auto a = cell->histograms(), b = imported.final->histograms();
        QCOMPARE(a.size(), b.size());
        for (std::size_t h = 0; h < a.size(); ++h)
            for (std::size_t bin = 0; bin < a[h].counts.bins(); ++bin)
                QCOMPARE(b[h].counts.count(bin), a[h].counts.count(bin));
    }

    void planarScatteringIsRefused() {
        const auto cell = cellFor("dsmc-planar-beams");
        QVERIFY_THROWS_EXCEPTION(scaleout::ExportError, scaleout::spartaDeck(*cell, {100, 1}));
    }
};

QTEST_GUILESS_MAIN(TestSpartaDeck)
#include "tst_sparta_deck.moc"
