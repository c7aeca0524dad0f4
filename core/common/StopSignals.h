// The terminating signals a user sends from a terminal or a session manager (INT, TERM, HUP, QUIT, USR1,
// USR2): a command-line program catches them so that a run stops between two steps and keeps what it
// measured, says so in one line and exits as the shell expects (128 + the signal's number).
#pragma once

#include <string>

namespace pl {

// Catches the stop signals for the life of the object (one at a time in a process). While the experiment
// is set up (reading, checks, building the model: nothing is written yet) a signal ends the process at
// once with one sentence on stderr, "<program>: stopped by SIGHUP while setting up the experiment;
// nothing was written", and the exit code 128 + N. Once runStarts() is called, the first signal asks the
// run to stop (requestStop(), common/StopRequest.h: a step of minutes is abandoned) and is caught(); a
// second one of the same kind ends the process at once, as without this.
class StopSignals {
public:
    explicit StopSignals(const char* program);
    ~StopSignals();
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;

    void runStarts(); // from here a signal is caught() instead of ending the set-up

    int caught() const;                                      // the signal's number, 0 while none came
    static std::string name(int signal);                     // "SIGINT"
    static int exitCode(int signal) { return 128 + signal; } // the shell's convention: 130, 143, 129
};

} // namespace pl
