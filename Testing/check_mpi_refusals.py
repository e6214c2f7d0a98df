"""What the docs say is refused on distributed data is what the filter refuses.

The ChainMail filter decides from its properties, the same on every process, what it
does not run on data split across processes (vtkChainMailDeformationFilterParallel.cxx,
the block after "Not distributed yet"). The class comment, the README and docs/mpi.md
each list it: every refusal in the code must be named in each list, and no list may name
what runs distributed (edits, a grasp by position, refinement with Envelope, geodesic
painting) as refused. Run by ctest as Docs.MpiRefusalsMatchTheFilter."""
import os
import re
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")

# topic: (what the code tests in its refusal block, what a list must say for it)
REFUSALS = {
    "refinement solvers other than Envelope, or the Link region":
        (r"RefinementSolver != REFINEMENT_ENVELOPE", r"(solvers?|Dykstra)"),
    "relaxation": (r"RelaxationIterations > 0", r"relaxation"),
    "obstacles": (r"GetNumberOfInputConnections\(1\)", r"obstacle"),
    "the Priority and Max Violation queues": (r"CandidateQueue != FIFO", r"Max\s+Violation"),
    "honoured markers": (r"HonourMarkers", r"markers"),
}
# What runs distributed: a refusal list naming it is false.
RUNS = [r"\bedit", r"\bcommit", r"\bundo", r"GraspPosition", r"grasp by position",
        r"[Gg]eodesic"]

# The lists: (file, a regular expression whose first group is the list).
LISTS = [
    ("Filters/Deformation/vtkChainMailDeformationFilter.h",
     r"Not distributed\s+\*?\s*yet, refused[^:]*:(.*?)\.\s*\*/"),
    ("README.md", r"\.\s+([^.]*?)are refused there"),
    ("docs/mpi.md", r"## Not distributed yet[^\n]*\n(.*?)\(Refinement"),
]


def read(path):
    with open(os.path.join(ROOT, path)) as f:
        return f.read()


def main():
    failures = []
    code = read("Filters/Deformation/vtkChainMailDeformationFilterParallel.cxx")
    block = re.search(r"Not distributed yet(.*?)if \(!refused\.empty\(\)\)", code, re.S)
    if not block:
        print("FAILED: the filter's refusal block was not found")
        return 1
    refused = [t for t, (pattern, _) in REFUSALS.items() if re.search(pattern, block.group(1))]
    if len(refused) != len(re.findall(r"refused\s*=", block.group(1))):
        failures.append("the filter refuses something this check does not know: add it to REFUSALS")
    for path, pattern in LISTS:
        found = re.search(pattern, read(path), re.S)
        if not found:
            failures.append("%s: the list of what is refused was not found" % path)
            continue
        text = " ".join(found.group(1).replace("*", " ").split())
        for topic in refused:
            if not re.search(REFUSALS[topic][1], text):
                failures.append("%s does not name %s as refused: %r" % (path, topic, text))
        for runs in RUNS:
            if re.search(runs, text):
                failures.append("%s names something that runs distributed (%s) as refused: %r"
                                % (path, runs, text))
    for failure in failures:
        print("FAILED:", failure)
    print("checked %d refusals against %d lists" % (len(refused), len(LISTS)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
