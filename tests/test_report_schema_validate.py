#!/usr/bin/env python3
# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Validates archgeo reports against docs/report.schema.json.

Usage: test_report_schema_validate.py SCHEMA REPORT.json...
Exit 0 if every report is valid, 1 otherwise (the errors on stderr).

"integer" is strict here: a JSON number with a fraction part or a decimal
point (3.0) is not an integer, so a count written as a float fails, which
plain JSON Schema (where 3.0 is an integer) would let through. Uses Debian's
python3-jsonschema (tools/install_deps.sh).
"""
import json
import sys

import jsonschema


def integer(checker, instance):
    return isinstance(instance, int) and not isinstance(instance, bool)


def main():
    schema = json.load(open(sys.argv[1]))
    base = jsonschema.Draft202012Validator
    base.check_schema(schema)
    strict = jsonschema.validators.extend(
        base, type_checker=base.TYPE_CHECKER.redefine("integer", integer))
    validator = strict(schema)
    failed = 0
    for path in sys.argv[2:]:
        report = json.load(open(path))
        errors = list(validator.iter_errors(report))
        for error in errors[:5]:
            for e in (error.context or [error])[:8]:
                where = "/".join(str(p) for p in e.absolute_path)
                print(f"{path}: /{where}: {e.message[:300]}", file=sys.stderr)
        failed += bool(errors)
    print(f"{len(sys.argv) - 2 - failed} valid, {failed} invalid")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
