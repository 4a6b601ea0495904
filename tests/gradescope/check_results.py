#!/usr/bin/env python3
"""Checks a Gradescope results.json: first against the fields Gradescope's autograder specification
documents (https://gradescope-autograders.readthedocs.io/en/latest/specs/, "Output format"), no
other field allowed, and those frob always writes; then against what the case expects.

Usage: check_results.py RESULTS [--score X] [--test NAME=SCORE/MAX]... [--hidden NAME]...
                                [--output-has TEXT]... [--scores-of OTHER_RESULTS]
"""
import argparse
import json
import sys

TOP_LEVEL = {"score", "execution_time", "output", "output_format", "test_output_format", "test_name_format",
             "visibility", "stdout_visibility", "extra_data", "tests", "leaderboard"}
TEST = {"score", "max_score", "status", "name", "name_format", "number", "output", "output_format", "tags",
        "visibility", "extra_data"}
VISIBILITIES = {"visible", "hidden", "after_due_date", "after_published"}
FORMATS = {"text", "html", "simple_format", "md", "ansi"}

problems = []


def expect(ok, what):
    if not ok:
        problems.append(what)


def number(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def check_shape(doc):
    if not isinstance(doc, dict):
        problems.append("not a JSON object")
        return
    expect(not set(doc) - TOP_LEVEL, f"fields Gradescope does not document: {sorted(set(doc) - TOP_LEVEL)}")
    # Documented as optional; frob always writes them.
    expect(number(doc.get("score")), f"'score' is not a number: {doc.get('score')!r}")
    expect(number(doc.get("execution_time")) and doc["execution_time"] >= 0,
           f"'execution_time' is not a number of seconds: {doc.get('execution_time')!r}")
    expect(isinstance(doc.get("output"), str), f"'output' is not a string: {doc.get('output')!r}")
    for key in ("output_format", "test_output_format", "test_name_format"):
        expect(key not in doc or doc[key] in FORMATS, f"'{key}' is {doc.get(key)!r}, not one of {sorted(FORMATS)}")
    for key in ("visibility", "stdout_visibility"):
        expect(key not in doc or doc[key] in VISIBILITIES, f"'{key}' is {doc.get(key)!r}, not one of {sorted(VISIBILITIES)}")
    expect("extra_data" not in doc or isinstance(doc["extra_data"], dict), "'extra_data' is not an object")
    tests = doc.get("tests")
    if not isinstance(tests, list):
        problems.append(f"'tests' is not a list: {tests!r}")
        return
    for t in tests:
        if not isinstance(t, dict):
            problems.append(f"a test is not an object: {t!r}")
            continue
        name = t.get("name")
        expect(not set(t) - TEST, f"test {name!r}: fields Gradescope does not document: {sorted(set(t) - TEST)}")
        expect(isinstance(name, str) and name, f"a test has no name: {t!r}")
        expect(number(t.get("score")) and number(t.get("max_score")) and 0 <= t["score"] <= t["max_score"],
               f"test {name!r}: not 0 <= score <= max_score: {t.get('score')!r} / {t.get('max_score')!r}")
        # Gradescope's own rule when status is left out: passed exactly when the test has all its points.
        full = number(t.get("score")) and t.get("score") == t.get("max_score")
        expect(t.get("status") == ("passed" if full else "failed"),
               f"test {name!r}: status {t.get('status')!r} for {t.get('score')!r} / {t.get('max_score')!r}")
        expect(isinstance(t.get("output"), str), f"test {name!r}: 'output' is not a string")
        expect(t.get("visibility") in VISIBILITIES, f"test {name!r}: visibility {t.get('visibility')!r}, not one of {sorted(VISIBILITIES)}")
        for key in ("output_format", "name_format"):
            expect(key not in t or t[key] in FORMATS, f"test {name!r}: '{key}' is {t.get(key)!r}")
        expect("tags" not in t or (isinstance(t["tags"], list) and all(isinstance(g, str) for g in t["tags"])),
               f"test {name!r}: 'tags' is not a list of strings")
        expect("number" not in t or isinstance(t["number"], str), f"test {name!r}: 'number' is not a string")
    scored = [t for t in tests if isinstance(t, dict) and number(t.get("score"))]
    if scored and number(doc.get("score")):
        earned = sum(t["score"] for t in scored)
        expect(abs(earned - doc["score"]) < 1e-9, f"the tests' scores add up to {earned}, not the score {doc['score']}")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("results")
    p.add_argument("--score", type=float)
    p.add_argument("--test", action="append", default=[], help="NAME=SCORE/MAX")
    p.add_argument("--hidden", action="append", default=[], help="NAME of a test that must be hidden")
    p.add_argument("--output-has", action="append", default=[])
    p.add_argument("--scores-of", help="another results.json (the host's) whose score and tests' scores these must be")
    a = p.parse_args()

    with open(a.results, "rb") as f:
        raw = f.read()
    try:
        doc = json.loads(raw)
    except ValueError as e:
        print(f"{a.results}: not JSON: {e}\n{raw[:2000]!r}", file=sys.stderr)
        return 1
    check_shape(doc)
    if isinstance(doc, dict):
        if a.score is not None:
            expect(number(doc.get("score")) and abs(doc["score"] - a.score) < 1e-9, f"score is {doc.get('score')!r}, not {a.score}")
        for text in a.output_has:
            expect(text in str(doc.get("output", "")), f"output lacks {text!r}")
        tests = {t.get("name"): t for t in doc.get("tests", []) if isinstance(t, dict)}
        for spec in a.test:
            name, _, score = spec.rpartition("=")
            points, _, most = score.partition("/")
            t = tests.get(name)
            if t is None:
                problems.append(f"no test {name!r} among {sorted(n for n in tests if n)}")
                continue
            expect((t.get("score"), t.get("max_score")) == (float(points), float(most)),
                   f"test {name!r}: {t.get('score')}/{t.get('max_score')}, not {points}/{most}: {t.get('output', '')!r}")
            expect(t.get("visibility") == ("hidden" if name in a.hidden else "visible"),
                   f"test {name!r}: visibility {t.get('visibility')!r}, not {'hidden' if name in a.hidden else 'visible'}")
        if a.test:
            expect(len(tests) == len(a.test), f"tests {sorted(n for n in tests if n)}, not the {len(a.test)} expected")
        if a.scores_of:
            with open(a.scores_of) as f:
                other = json.load(f)
            scores = lambda d: (d.get("score"), [(t.get("name"), t.get("score"), t.get("max_score")) for t in d.get("tests", [])])
            expect(scores(doc) == scores(other), f"the scores {scores(doc)} are not those of {a.scores_of}: {scores(other)}")
    if problems:
        print(f"{a.results}:\n  " + "\n  ".join(problems), file=sys.stderr)
        print(json.dumps(doc, indent=2)[:5000], file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
