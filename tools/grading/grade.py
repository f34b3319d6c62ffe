#!/usr/bin/python3
"""Grades student submissions of the Shadow Lab Workbook: ./workbook grade (see docs/instructors.md).

A submission is a folder or an archive (.zip, .tar, .tar.gz, .tgz) holding a student's copy of the
workbook, or just its labs/ folder, or (when one lab is graded) just the exercise files, flat. Only
the exercise files that labs/*/exercises.json names are taken from it. They go into a copy of this
tree without the instructor material, prebuilt, where an unprivileged user compiles them (one
compile per lab) and another runs them as the *runner*, without network, recording what the
exercises produce; the solution's build, the *judge*, decides every score from that record and draws
every graded scene itself (docs/grading-trust.md). A build that runs past --build-timeout is stopped
and costs the exercises it was building; whatever else goes wrong with one submission (even a fault
of the grader) is recorded in its results, never stops a batch.

Outputs per submission (in --out): results.json (Gradescope, rewritten after every exercise so a
crash mid-way leaves a valid file), junit.xml, report.md and report.html with the pictures of failed
tests (a scene's reference, result and difference; a sweep's plot). With --batch: one such folder per student, gradebook.csv and
summary.md.
"""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # tools/, run as a script or loaded by path

from grading.batch import grade_all, hide_from_sandbox, main, salvage, write_batch_outputs
from grading.chunks import chunk, find_marker, keep_only_chunks
from grading.common import ROOT
from grading.grader import Grader, grader_failed
from grading.report import VISIBILITIES, Results, gradescope_visibility, student_visible
from grading.sandbox import Sandbox
from grading.submission import find_student_file, load_labs, unique_names, unpack
from grading.workspace import Workspace

# What this module offers besides main(): the grader's parts, imported from here by tests/grading.
__all__ = ["Grader", "ROOT", "Results", "Sandbox", "VISIBILITIES", "Workspace", "chunk", "find_marker",
           "find_student_file", "grade_all", "gradescope_visibility", "grader_failed", "hide_from_sandbox",
           "keep_only_chunks", "load_labs", "main", "salvage", "student_visible", "unique_names", "unpack",
           "write_batch_outputs"]

if __name__ == "__main__":
    sys.exit(main())
