// Runs particlelab-cli (or another of the headless programs) as a user does, for the CLI's tests: exit
// code, signal, output, with a time limit.
#pragma once

#include <QProcess>
#include <QProcessEnvironment>
#include <QString>
#include <QStringList>

namespace pl::test {

struct CliResult {
    int exitCode = -1;
    bool crashed = false;  // ended by a signal
    bool timedOut = false; // killed at the time limit
    QString startError;    // why the process could not be started (not the CLI's fault)
    QString out, err;
};

inline CliResult
runProgram(const QString& program, const QStringList& args, int timeoutMs = 120000,
           const QString& workingDir = {},
           const QProcessEnvironment& environment = QProcessEnvironment::systemEnvironment()) {
    QProcess p;
    if (!workingDir.isEmpty()) p.setWorkingDirectory(workingDir);
    p.setProcessEnvironment(environment);
    p.start(program, args);
    CliResult r;
    if (!p.waitForStarted(timeoutMs)) {
        r.startError = p.errorString();
        return r;
    }
    if (!p.waitForFinished(timeoutMs)) {
        r.timedOut = true;
        p.kill();
        p.waitForFinished();
    }
    r.crashed = !r.timedOut && p.exitStatus() == QProcess::CrashExit;
    r.exitCode = p.exitCode();
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

inline CliResult runCli(const QStringList& args, int timeoutMs = 120000, const QString& workingDir = {}) {
    return runProgram(PARTICLELAB_CLI, args, timeoutMs, workingDir);
}

} // namespace pl::test
