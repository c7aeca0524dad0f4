// particlelab-cli: run, benchmark and list experiments without a display.
#include "Commands.h"
#include "MethodsCommands.h"
#include "OptionChecks.h"
#include "ScaleOutCommands.h"
#ifdef PARTICLELAB_RECORDING
#include "MediaCommands.h"
#include "MediaModule.h"
#endif
#include "common/AtomicFile.h"
#include "common/ThreadGovernor.h"

#include <CLI/CLI.hpp>
#include <iostream>
#include <limits>

namespace {

constexpr const char* kThreadsHelp =
    "OpenMP threads, fixed (default: each step on the team the run measures fastest, up to all cores)";

// The help command of the subcommand being parsed, else of the program.
std::string helpCommand(const CLI::App& app) {
    for (const CLI::App* sub : app.get_subcommands()) return "particlelab-cli " + sub->get_name() + " --help";
    return "particlelab-cli --help";
}

} // namespace

int main(int argc, char** argv) {
    using namespace pl::cli;
    // Every subcommand steps on the fastest team it measures; run and bench take --threads to fix it.
    pl::setThreadPolicy(pl::adaptiveUnlessUserFixed());
    CLI::App app{"ParticleLab headless runner: list presets, run experiments to CSV, benchmark"};
    app.require_subcommand(1);
    app.set_version_flag("--version", std::string("particlelab-cli ") + PARTICLELAB_VERSION,
                         "Print the program's version and exit");

    app.add_subcommand("list", "List the built-in presets with a one-line description");

    std::string columnsScene;
    auto* columnsCmd = app.add_subcommand(
        "columns", "List a scene's series columns, the CSV header of run: name, unit, label");
    columnsCmd->add_option("scene", columnsScene, "A scene (" + sceneKinds() + ") or a preset")->required();
    columnsCmd->footer(sceneUnits());

    RunOptions run;
    auto* runCmd = app.add_subcommand("run", "Run a preset and write observables as CSV");
    runCmd->add_option("preset", run.preset, "Built-in preset name or preset file")->required();
    runCmd
        ->add_option("--steps", run.steps,
                     "Number of steps (default: what is left of the preset's run length, else 1000)")
        ->transform(wholeNumber(0, kMaxSteps, "10⁹ steps are days of computing even for a small scene"));
    runCmd->add_option("--set", run.sets,
                       "Override a parameter: key=value (repeatable), in the scene's units");
    runCmd->add_option("--seed", run.seed, "Random seed (default: the preset's)")
        ->transform(wholeNumber(0, std::numeric_limits<long long>::max()));
    runCmd->add_option("--threads", run.threads, kThreadsHelp)->transform(threadCount());
    runCmd
        ->add_option("--every", run.every,
                     "Sample observables every K steps (default: every step of a preset with a run "
                     "length, else 100)")
        ->transform(wholeNumber(1, kMaxSteps));
    runCmd->add_option("--out", run.out, "Time series CSV, written row by row as it is sampled")
        ->check(fileName());
    runCmd->add_option("--histogram", run.histogram, "Final histograms CSV (speed; v_x for DSMC)")
        ->check(fileName());
    runCmd
        ->add_option("--dump-initial", run.dumpInitial,
                     "Initial particles CSV, one row per particle; the header names each scene's columns "
                     "(gas: id,species,x,y,vx,vy)")
        ->check(fileName());
    runCmd->add_option("--dump-final", run.dumpFinal, "Final particles CSV, as --dump-initial")
        ->check(fileName());
    runCmd
        ->add_option("--fields", run.fields,
                     "Wind tunnel: the sampled fields at the end (also when stopped), one row per cell: "
                     "i,j,x,y,n,ux,uy,T,Tx,Ty,mach (SI)")
        ->check(fileName());
    runCmd
        ->add_option(
            "--surface", run.surface,
            "Wind tunnel: the force on the bodies per sample, step,time,drag,lift [N per m of depth]")
        ->check(fileName());
    runCmd
        ->add_option("--snapshot", run.snapshot,
                     "Full state at the end (also when stopped); `run FILE` continues from it exactly")
        ->check(fileName());
    runCmd->add_flag("--quiet", run.quiet, "No progress line");
    runCmd->add_flag("--allow-unstable", run.allowUnstable,
                     "Run a step known to be unstable (the gas: dt·ω above its integrator's limit) instead "
                     "of refusing it (exit 2); warned on stderr and in the first line of --out");
    runCmd
        ->add_option("--backend", run.backend,
                     "cpu, gl (OpenGL 4.3 compute) or auto (the GPU for large scenes)")
        ->check(CLI::IsMember({"cpu", "gl", "auto"}));
    runCmd->footer(sceneUnits());

    BenchOptions bench;
    auto* benchCmd =
        app.add_subcommand("bench", "Time a preset; print one JSON line with particle-steps per second");
    benchCmd->add_option("preset", bench.preset, "Built-in preset name or preset file")->required();
    benchCmd->add_option("--steps", bench.steps, "Timed steps per repeat")
        ->transform(wholeNumber(1, kMaxSteps));
    benchCmd->add_option("--set", bench.sets,
                         "Override a parameter: key=value (repeatable), in the scene's units");
    benchCmd->add_option("--threads", bench.threads, kThreadsHelp)->transform(threadCount());
    benchCmd->add_option("--backend", bench.backend, "cpu, gl or auto")
        ->check(CLI::IsMember({"cpu", "gl", "auto"}));
    benchCmd->add_option("--repeats", bench.repeats, "Timed repeats; the median is reported")
        ->transform(wholeNumber(1, 1000));
    benchCmd->footer(sceneUnits());

    EchoOptions echo;
    auto* echoCmd = app.add_subcommand(
        "echo", "Time reversal measured: run n steps forward and n back, print the rms return error (CSV)");
    echoCmd->add_option("--disks", echo.disks, "Disks in the periodic box (square lattice)")
        ->transform(wholeNumber(2, 4096));
    echoCmd->add_option("--steps", echo.steps, "Values of n (default 10 30 … 10000)")
        ->transform(wholeNumber(1, kMaxSteps / 2));
    echoCmd->add_option("--out", echo.out, "CSV file (default: standard output)")->check(fileName());

    SweepOptions sweep;
    auto* sweepCmd = app.add_subcommand(
        "sweep", "Accuracy against cost of the gas's integrators on a harmonic pair (CSV; orders on stderr)");
    sweepCmd
        ->add_option("--integrators", sweep.integrators,
                     "Schemes to compare (default: all):\n" + pl::gasIntegratorHelp())
        ->check(CLI::IsMember(pl::gasIntegratorNames()));
    sweepCmd->add_option("--steps", sweep.steps, "Steps over the horizon, one run each (default 16 … 256)")
        ->transform(wholeNumber(1, 1'000'000));
    sweepCmd->add_option("--stiffness", sweep.stiffness, "k of the contact [M/T²]")->check(positiveReal());
    sweepCmd->add_option("--from", sweep.from,
                         "A gas preset: sweep from its state, errors against a Forest–Ruth reference");
    sweepCmd->add_option("--set", sweep.sets, "Override a parameter of --from: key=value (repeatable)");
    sweepCmd
        ->add_option("--horizon", sweep.horizon, "Simulated time of each run from --from (default 64 steps)")
        ->check(positiveReal(true));
    sweepCmd->add_option("--out", sweep.out, "CSV file (default: standard output)")->check(fileName());

    StabilityOptions stability;
    auto* stabilityCmd = app.add_subcommand(
        "stability",
        "Stability map of the gas's integrators: dt × stiffness, each cell stable, inaccurate or "
        "unstable (CSV; measured limits on stderr)");
    stabilityCmd
        ->add_option("--integrators", stability.integrators,
                     "Schemes (default: all):\n" + pl::gasIntegratorHelp())
        ->check(CLI::IsMember(pl::gasIntegratorNames()));
    stabilityCmd->add_option("--omega-dt", stability.omegaDt, "ω dt of the columns (default 0.05 … 5)")
        ->check(positiveReal());
    stabilityCmd->add_option("--stiffness", stability.stiffness, "k of the rows (default 100 1000 10000)")
        ->check(positiveReal());
    stabilityCmd->add_option("--steps", stability.steps, "Steps per cell")
        ->transform(wholeNumber(1, kMaxSteps));
    stabilityCmd
        ->add_option("--tolerance", stability.tolerance, "Energy error above which a cell is inaccurate")
        ->check(positiveReal());
    stabilityCmd->add_option("--out", stability.out, "CSV file (default: standard output)")
        ->check(fileName());

    FluidSweepOptions fluid;
    auto* fluidCmd = app.add_subcommand(
        "fluid-sweep", "The fluid against dt × iterations: density error, cost, stable / over-compressed / "
                       "exploded (CSV)");
    fluidCmd->add_option("--dt", fluid.dt, "Time steps [s]")->check(positiveReal());
    fluidCmd->add_option("--iterations", fluid.iterations, "Solver iterations")
        ->transform(wholeNumber(1, 100));
    fluidCmd->add_option("--duration", fluid.duration, "Simulated time of each cell [s]")
        ->check(positiveReal());
    fluidCmd->add_option("--tolerance", fluid.tolerance, "Mean density error that counts as over-compressed")
        ->check(positiveReal());
    fluidCmd->add_option("--out", fluid.out, "CSV file (default: standard output)")->check(fileName());

    DsmcSweepOptions dsmc;
    auto* dsmcCmd = app.add_subcommand(
        "dsmc-sweep", "DSMC against the exact BKW relaxation: particles × ν dt, moment error and cost (CSV)");
    dsmcCmd->add_option("--particles", dsmc.particles, "Particles in the cell")
        ->transform(wholeNumber(2, 1 << 24));
    dsmcCmd->add_option("--nu-dt", dsmc.nuDt, "Collision probabilities per particle and step")
        ->check(positiveReal());
    dsmcCmd->add_option("--out", dsmc.out, "CSV file (default: standard output)")->check(fileName());

    RelaxOptions relax;
    auto* relaxCmd = app.add_subcommand(
        "relax", "MD against planar DSMC from the same two beams: kurtosis of v_x against collisions per "
                 "particle (CSV; cost ratio and KS test on stderr)");
    relaxCmd->add_option("--particles", relax.particles, "Particles of each")
        ->transform(wholeNumber(4, 1 << 20));
    relaxCmd->add_option("--collisions", relax.collisions, "Collisions per particle to run")
        ->check(CLI::Range(0.1, 1000.0));
    relaxCmd->add_option("--seed", relax.seed, "Random seed of the shared start")
        ->transform(wholeNumber(0, std::numeric_limits<long long>::max()));
    relaxCmd->add_option("--out", relax.out, "CSV file (default: standard output)")->check(fileName());

#ifdef PARTICLELAB_RECORDING
    RecordOptions record;
    auto* recordCmd = app.add_subcommand(
        "record",
        "Record a clip (MP4, WebM or GIF by the suffix of --out) in simulated time, without a display");
    recordCmd->add_option("preset", record.preset, "Built-in preset name, preset file or snapshot")
        ->required();
    recordCmd
        ->add_option("--out", record.out,
                     "The clip: .mp4 (H.264), .webm (VP9) or .gif; written as it "
                     "is recorded, and playable when stopped")
        ->required()
        ->check(fileName());
    recordCmd->add_option("--seconds", record.seconds, "Length of the clip [s] (default 10)")
        ->check(positiveReal(false, 3600.0));
    recordCmd->add_option("--fps", record.fps, "Frames per second of the clip (default 30)")
        ->transform(wholeNumber(1, 120));
    recordCmd
        ->add_option("--steps-per-frame", record.stepsPerFrame,
                     "Model steps between two frames: the simulated time a frame shows (default 10)")
        ->transform(wholeNumber(1, 100000));
    recordCmd->add_option("--size", record.size, "Frame size WIDTHxHEIGHT in pixels (default 1280x720)");
    recordCmd->add_option("--plot", record.plot, "A plot of the scene beside it, by name (e.g. energyPlot)");
    recordCmd->add_flag("--no-captions", record.noCaptions,
                        "No title over the first second and no time readout");
    recordCmd->add_option("--set", record.sets,
                          "Override a parameter: key=value (repeatable), in the scene's units");
    recordCmd->add_option("--seed", record.seed, "Random seed (default: the preset's)")
        ->transform(wholeNumber(0, std::numeric_limits<long long>::max()));
    recordCmd->add_option("--threads", record.threads, kThreadsHelp)->transform(threadCount());
    recordCmd->add_option("--backend", record.backend, "cpu, gl or auto")
        ->check(CLI::IsMember({"cpu", "gl", "auto"}));
    recordCmd->add_flag("--quiet", record.quiet, "No progress line and no summary");
    recordCmd->footer(sceneUnits());

    ReportOptions report;
    auto* reportCmd = app.add_subcommand(
        "report", "Run an experiment and write its lab report: PDF, or one self-contained HTML page (.html)");
    reportCmd->add_option("preset", report.preset, "Built-in preset name, preset file or snapshot")
        ->required();
    reportCmd->add_option("--out", report.out, "The report: .pdf or .html")->required()->check(fileName());
    reportCmd->add_option(
        "--data", report.dataDir,
        "A folder for the plots' data beside the report, one CSV per plot (made if missing)");
    reportCmd
        ->add_option("--steps", report.steps,
                     "Steps to run first (default: the preset's run length, else what a class watches in 4 s "
                     "at the scene's watchable pace, at least 1000)")
        ->transform(wholeNumber(0, kMaxSteps));
    reportCmd->add_option("--set", report.sets,
                          "Override a parameter: key=value (repeatable), in the scene's units");
    reportCmd->add_option("--seed", report.seed, "Random seed (default: the preset's)")
        ->transform(wholeNumber(0, std::numeric_limits<long long>::max()));
    reportCmd->add_option("--threads", report.threads, kThreadsHelp)->transform(threadCount());
    reportCmd->add_option("--backend", report.backend, "cpu, gl or auto")
        ->check(CLI::IsMember({"cpu", "gl", "auto"}));
    reportCmd->footer(sceneUnits());
#endif

    ScaleOutCli scaleOut(app);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e); // --help, --version: the text, exit 0
        std::cerr << "particlelab-cli: " << e.what() << "; see '" << helpCommand(app) << "'\n";
        return kBadInput;
    }
    // The methods lab's sweeps write at the end: their file is checked before they start.
    for (const std::string* out :
         {&echo.out, &sweep.out, &stability.out, &fluid.out, &dsmc.out, &relax.out}) {
        try {
            if (!out->empty()) pl::checkOutputPath(*out);
        } catch (const pl::FileError& e) {
            std::cerr << "particlelab-cli: " << e.what() << "\n";
            return kCannotWrite;
        }
    }
    if (auto code = scaleOut.runChosen()) return *code;
    if (app.got_subcommand("stability")) return stabilityMap(stability);
    if (app.got_subcommand("fluid-sweep")) return fluidSweep(fluid);
    if (app.got_subcommand("dsmc-sweep")) return dsmcSweep(dsmc);
    if (app.got_subcommand("relax")) return relaxMdDsmc(relax);
    if (app.got_subcommand("echo")) return loschmidtEcho(echo);
    if (app.got_subcommand("sweep")) return integratorSweep(sweep);
    if (app.got_subcommand("list")) return listPresets();
    if (app.got_subcommand("columns")) return listColumns(columnsScene);
    if (app.got_subcommand("run")) return runSimulation(run);
#ifdef PARTICLELAB_RECORDING
#ifdef PARTICLELAB_MEDIA_PROGRAM
    if (app.got_subcommand("record")) return recordClip(record);
    if (app.got_subcommand("report")) return writeReport(report);
#else
    if (app.got_subcommand("record")) { // a clip that cannot be made is refused before Qt starts
        pl::ClipFormat format{};
        int width = 0, height = 0;
        long long frames = 0;
        if (const std::string refusal = pl::cli::recordOptionsRefusal(record, format, width, height, frames);
            !refusal.empty()) {
            std::cerr << "particlelab-cli: " << refusal << "\n";
            return kBadInput;
        }
    }
    if (app.got_subcommand("record") || app.got_subcommand("report")) return execMediaProgram(argv);
#endif
#endif
    return benchmark(bench);
}
