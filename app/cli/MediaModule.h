// record and report run in a second program, particlelab-cli-media, that particlelab-cli becomes (exec,
// the same process and arguments) only for them: it links Qt's GUI and FFmpeg's libraries, whose loading
// would otherwise add some 60 ms to the start of every particlelab-cli call (list, run, the fuzzed
// thousands), which need neither. Both programs are built from main.cpp and parse the same options.
#pragma once

namespace pl::cli {

// Replaces this process with particlelab-cli-media (beside the program, else in its installed folder)
// with the same arguments. Returns only when it cannot, having said why in one sentence (exit code 2).
int execMediaProgram(char** argv);

} // namespace pl::cli
