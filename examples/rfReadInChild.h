// A reader's first run in a child process: VTK 9.1's readers trust their files, and a
// malformed one (a legacy .vtk whose counts disagree with its data, a PLY body shorter than its
// header says, ...) can crash them. The viewer runs each reader once in a child first, so such
// a file is refused with a message and the viewer goes on; its checks of the declared sizes
// (rfDeclaredSizes.h) refuse the files that would have the reader allocate too much. Found by
// fuzzing the viewer's inputs (tests/fuzz/fuzz_files.cxx). The child runs VTK's parallel loops
// in its one thread (the parent's thread pool is not forked); a child that stops using the
// processor for 5 seconds is stopped and taken for a yes. POSIX only; elsewhere it reads
// nothing and says yes.
#ifndef rfReadInChild_h
#define rfReadInChild_h

#include <string>

class vtkAlgorithm;

// Updates `reader` in a child process: true when it ran to its end, else false and, in
// `error`, how it ended. The caller's reader is left as it was (the child's work is lost).
bool rfReadsWithoutCrashing(vtkAlgorithm* reader, std::string& error);

#endif
