#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# run-with-shared-data.sh DIR COMMAND...: run COMMAND when the shared data DIR exists;
# otherwise skip (exit 77), or fail under CI=true.
dir=$1
shift
if [ ! -d "$dir" ]; then
  if [ "${CI:-}" = "true" ] || [ "${CI:-}" = "1" ]; then
    echo "shared test data missing under CI: $dir" >&2
    exit 1
  fi
  echo "shared test data missing, skipped: $dir" >&2
  exit 77
fi
exec "$@"
