/// @file exercise_chunks.hpp
/// An exercise shader file is cut into chunks by its markers: "// EXERCISE 09.2" starts exercise
/// 09.2's chunk, which runs to the next marker or the end; the text above the first marker (shared
/// helpers) is the chunk "". Isolation swaps other exercises' chunks for the solution's
/// (glsl_harness.hpp); hot reload swaps a chunk that no longer compiles for its last good text
/// (shader.hpp); a file that does not compile is blamed on the chunks that fail alone, found by
/// compiling (chunksThatDoNotCompile). Only text here: no GL (the compiler is the caller's).
#pragma once
#include <functional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace wb {

/// Where exercise `id`'s marker "// EXERCISE <id>" is in `text`: the exact id, followed by a space,
/// a colon or the line's end (so "// EXERCISE 01" is not 01.3's marker), or npos.
size_t findMarker(const std::string& text, const std::string& id);

/// [begin, end) of the chunk of `id`: from the start of its marker's line to the start of the next
/// marker's line, or the end. Throws wb::Error when `text` has no marker for `id`.
std::pair<size_t, size_t> chunkRange(const std::string& text, const std::string& id);

/// True when exercise `id`'s chunk of `text` still holds the stub's WB_TODO (not implemented yet);
/// false when `text` has no marker for `id`.
bool chunkIsStub(const std::string& text, const std::string& id);

/// The chunks of `text` in order, as (id, text): the preamble "" first (when not empty), then one
/// per marker. Joined, they are `text` again.
std::vector<std::pair<std::string, std::string>> splitChunks(const std::string& text);

/// The ids (the preamble "" included) whose chunk differs between `before` and `after`, or that
/// only one of them has.
std::set<std::string> changedChunks(const std::string& before, const std::string& after);

/// `current` with the chunks of `ids` taken from `lastGood` (where it has them), and `#line` directives
/// (source kThisFileSource, shader.hpp) so that every other chunk keeps its line numbers in the
/// compiler's messages.
std::string withChunksFrom(const std::string& current, const std::string& lastGood, const std::set<std::string>& ids);

/// `mine` with every other exercise's chunk taken from `stub`: how chunksThatDoNotCompile() compiles
/// exercise `id` alone (only chunks the stub has, of an exercise id's shape, are swapped).
std::string chunkAlone(const std::string& mine, const std::string& stub, const std::string& id);

/// What fillMissingChunks() did: the file, and the exercises whose stubs it put in.
struct FilledChunks {
  std::string text;                ///< the file, with the stubs of what it lacked
  std::vector<std::string> added;  ///< the exercises whose stubs were put in, in the stub's order
};

/// `mine`, written against an earlier edition of the lab, with every exercise the stub has and `mine`
/// lacks (no marker, and none of its functions defined) filled in from `stub`: that exercise is then
/// "not implemented" (or, for a bug hunt, still has its bug), and every other one is graded as
/// written. Each chunk goes before the marker of the next exercise `mine` has, in the stub's order,
/// or at the end, inside the file's closing "}  // namespace". An exercise whose function `mine`
/// defines without its marker (a deleted marker) is left alone.
FilledChunks fillMissingChunks(const std::string& mine, const std::string& stub);
/// The one line `check` and the grader print for an exercise fillMissingChunks() added to `file`
/// from `stubPath`: `check` put the stub into the student's file (`inPlace`), the grader graded it in
/// its place.
std::string filledChunkLine(const std::string& file, const std::string& id, const std::string& stubPath, bool inPlace);

/// Whether a whole exercise file compiles, as some program or kernel reads it (the caller's GL).
using CompilesFn = std::function<bool(const std::string& text)>;

/// The exercises whose chunks keep `mine` from compiling, decided by compiling and never by reading a
/// compiler's log: vendors word, number and cascade errors differently (NVIDIA follows a missing ';'
/// with errors in functions that are fine). Each exercise chunk of `mine` is compiled alone, every
/// other exercise's chunk taken from `stub` (the file as handed out, or its last text that compiled);
/// the chunks that fail alone are the ones, when `mine` compiles with all of them swapped for the
/// stub's. Empty when that cannot be told: no stub, an error outside the chunks (the helpers above
/// the first marker), or one that only chunks together make. Costs a compile per chunk, and one.
std::set<std::string> chunksThatDoNotCompile(const std::string& mine, const std::string& stub,
                                             const CompilesFn& compiles);

/// The line that names chunksThatDoNotCompile()'s exercises in a log, where the judge reads them
/// (culpritsIn()): the same words on every GL implementation.
std::string culpritLine(const std::set<std::string>& ids);
/// The exercises a log's culpritLine() names; empty when it has none.
std::set<std::string> culpritsIn(const std::string& log);

}  // namespace wb
