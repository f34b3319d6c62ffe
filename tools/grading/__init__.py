"""The grader of the Shadow Lab Workbook (./workbook grade; tools/grading/grade.py is its command line).
One job per module: submission (manifests, archives), sandbox (where student code runs, with its
limits), workspace (the runner's and the judge's builds), chunks (exercise chunks, build messages),
grader (one submission: runner and judge), report (results.json, junit.xml, reports), batch (a
class, and the command line). docs/grading-trust.md says why each part is as it is."""
