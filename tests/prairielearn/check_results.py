#!/usr/bin/env python3
"""Checks a PrairieLearn results.json: first the shape PrairieLearn's external grading documentation
gives it (and its <pl-external-grader-results> element reads), then what the case expects.

Usage: check_results.py RESULTS [--gradable true|false] [--score X] [--message TEXT] [--message-has TEXT]
                                [--output-has TEXT] [--format-errors-has TEXT] [--test NAME=POINTS/MAX]... [--no-tests]
"""
import argparse
import json
import os
import sys

problems = []


def expect(ok, what):
    if not ok:
        problems.append(what)


def number(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def check_shape(doc, size):
    expect(size < 1_000_000, f"the file is {size} bytes: PrairieLearn takes at most 1 MB")
    if not isinstance(doc, dict):
        problems.append("not a JSON object")
        return
    expect(isinstance(doc.get("gradable"), bool), "'gradable' is not true or false")
    gradable = doc.get("gradable", True)
    if gradable:
        expect(number(doc.get("score")) and 0.0 <= doc["score"] <= 1.0, f"'score' is not a number in [0, 1]: {doc.get('score')!r}")
    else:
        errors = doc.get("format_errors")
        listed = [errors] if isinstance(errors, str) else errors
        expect(isinstance(listed, list) and listed and all(isinstance(e, str) and e for e in listed),
               f"not gradable, and 'format_errors' is not a string or a list of strings: {errors!r}")
    for key in ("message", "output"):
        expect(isinstance(doc.get(key, ""), str), f"'{key}' is not a string")
    tests = doc.get("tests", [])
    expect(isinstance(tests, list), "'tests' is not a list")
    if not isinstance(tests, list):
        return
    for t in tests:
        if not isinstance(t, dict):
            problems.append(f"a test is not an object: {t!r}")
            continue
        expect(isinstance(t.get("name"), str) and t["name"], f"a test has no name: {t!r}")
        expect(number(t.get("points")) and number(t.get("max_points")) and 0 <= t["points"] <= t["max_points"],
               f"test {t.get('name')!r}: not 0 <= points <= max_points: {t!r}")
        for key in ("message", "output", "description"):
            expect(isinstance(t.get(key, ""), str), f"test {t.get('name')!r}: '{key}' is not a string")
    scored = [t for t in tests if isinstance(t, dict) and number(t.get("points")) and number(t.get("max_points"))]
    total = sum(t["max_points"] for t in scored)
    if gradable and scored and total > 0 and number(doc.get("score")):
        earned = sum(t["points"] for t in scored)
        expect(abs(earned / total - doc["score"]) < 1e-3, f"the tests' points, {earned}/{total}, are not the score {doc['score']}")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("results")
    p.add_argument("--gradable", choices=["true", "false"])
    p.add_argument("--score", type=float)
    p.add_argument("--message")
    p.add_argument("--message-has")
    p.add_argument("--output-has")
    p.add_argument("--format-errors-has")
    p.add_argument("--test", action="append", default=[], help="NAME=POINTS/MAX")
    p.add_argument("--no-tests", action="store_true")
    a = p.parse_args()

    with open(a.results, "rb") as f:
        raw = f.read()
    try:
        doc = json.loads(raw)
    except ValueError as e:
        print(f"{a.results}: not JSON: {e}\n{raw[:2000]!r}", file=sys.stderr)
        return 1
    check_shape(doc, os.path.getsize(a.results))
    if isinstance(doc, dict):
        if a.gradable is not None:
            expect(doc.get("gradable") is (a.gradable == "true"), f"gradable is {doc.get('gradable')!r}, not {a.gradable}")
        if a.score is not None:
            expect(number(doc.get("score")) and abs(doc["score"] - a.score) < 1e-9, f"score is {doc.get('score')!r}, not {a.score}")
        if a.message is not None:
            expect(doc.get("message") == a.message, f"message is {doc.get('message')!r}, not {a.message!r}")
        if a.message_has is not None:
            expect(a.message_has in doc.get("message", ""), f"message {doc.get('message')!r} lacks {a.message_has!r}")
        if a.output_has is not None:
            expect(a.output_has in doc.get("output", ""), f"output lacks {a.output_has!r}")
        if a.format_errors_has is not None:
            errors = doc.get("format_errors", "")
            text = "\n".join(errors) if isinstance(errors, list) else str(errors)
            expect(a.format_errors_has in text, f"format_errors {text[:500]!r} lacks {a.format_errors_has!r}")
        tests = {t.get("name"): t for t in doc.get("tests", []) if isinstance(t, dict)}
        for spec in a.test:
            name, _, score = spec.rpartition("=")
            points, _, most = score.partition("/")
            t = tests.get(name)
            if t is None:
                problems.append(f"no test {name!r} among {sorted(n for n in tests if n)}")
                continue
            expect((t.get("points"), t.get("max_points")) == (float(points), float(most)),
                   f"test {name!r}: {t.get('points')}/{t.get('max_points')}, not {points}/{most}: {t.get('output', '')!r}")
        if a.test:
            expect(len(tests) == len(a.test), f"tests {sorted(n for n in tests if n)}, not the {len(a.test)} expected")
        if a.no_tests:
            expect(doc.get("tests", []) == [], f"tests {doc.get('tests')!r}, not none")
    if problems:
        print(f"{a.results}:\n  " + "\n  ".join(problems), file=sys.stderr)
        print(json.dumps(doc, indent=2)[:5000], file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
