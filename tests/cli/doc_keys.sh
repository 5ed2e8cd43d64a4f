#!/usr/bin/env bash
# The user manual against the code (scripts/check_doc_keys.py): every key a command reads is documented in
# docs/commands, no documented key is refused, and no page links outside the repository or to a missing file.
set -u
exec /usr/bin/python3 "$(dirname "$0")/../../scripts/check_doc_keys.py" "$1"
