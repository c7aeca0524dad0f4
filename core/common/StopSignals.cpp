// The stop signals' handler: during the set-up it writes a prepared sentence and exits, afterwards it
// records the signal and asks the run to stop. Only async-signal-safe calls in the handler.
#include "StopSignals.h"

#include "StopRequest.h"

#include <algorithm>
#include <array>
#include <csignal>
#include <cstdio>
#include <unistd.h>

namespace pl {

namespace {

struct CaughtSignal {
    int number;
    const char* name;
};
// USR1 and USR2 are used by nothing else in these programs; a user or a batch system sends them to ask
// for a stop, as with TERM.
constexpr std::array<CaughtSignal, 6> kStopSignals{{{SIGINT, "SIGINT"},
                                                    {SIGTERM, "SIGTERM"},
                                                    {SIGHUP, "SIGHUP"},
                                                    {SIGQUIT, "SIGQUIT"},
                                                    {SIGUSR1, "SIGUSR1"},
                                                    {SIGUSR2, "SIGUSR2"}}};

volatile std::sig_atomic_t caughtSignal = 0;
volatile std::sig_atomic_t settingUp = 0;

// The set-up's sentence for each signal, made before any handler is installed: the handler only calls
// write(2) and _exit(2).
constexpr std::size_t kMessageBytes = 160;
std::array<std::array<char, kMessageBytes>, kStopSignals.size()> setUpMessages{};
std::array<int, kStopSignals.size()> setUpMessageLengths{};
std::array<struct sigaction, kStopSignals.size()> previous{};

extern "C" void onStopSignal(int signal) {
    if (settingUp) {
        for (std::size_t i = 0; i < kStopSignals.size(); ++i)
            if (kStopSignals[i].number == signal) {
                [[maybe_unused]] const ssize_t written =
                    ::write(2, setUpMessages[i].data(), static_cast<std::size_t>(setUpMessageLengths[i]));
            }
        ::_exit(128 + signal);
    }
    caughtSignal = signal;
    requestStop(); // a step of minutes polls it and is undone (common/StopRequest.h)
}

} // namespace

StopSignals::StopSignals(const char* program) {
    caughtSignal = 0;
    withdrawStopRequest();
    for (std::size_t i = 0; i < kStopSignals.size(); ++i) {
        const int length =
            std::snprintf(setUpMessages[i].data(), kMessageBytes,
                          "%s: stopped by %s while setting up the experiment; nothing was written\n", program,
                          kStopSignals[i].name);
        setUpMessageLengths[i] = std::min(length, static_cast<int>(kMessageBytes) - 1);
    }
    settingUp = 1;
    struct sigaction action {};
    action.sa_handler = onStopSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND; // a second signal finds the default action: it ends the process
    for (std::size_t i = 0; i < kStopSignals.size(); ++i)
        sigaction(kStopSignals[i].number, &action, &previous[i]);
}

StopSignals::~StopSignals() {
    for (std::size_t i = 0; i < kStopSignals.size(); ++i)
        sigaction(kStopSignals[i].number, &previous[i], nullptr);
    settingUp = 0;
}

void StopSignals::runStarts() {
    settingUp = 0;
}

int StopSignals::caught() const {
    return caughtSignal;
}

std::string StopSignals::name(int signal) {
    for (const CaughtSignal& s : kStopSignals)
        if (s.number == signal) return s.name;
    return "signal " + std::to_string(signal);
}

} // namespace pl
