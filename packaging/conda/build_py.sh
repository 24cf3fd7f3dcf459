#!/bin/bash
# trigspline (Python): pip with the host environment's setuptools, wheel and
# numpy (conda-build provides them: no build isolation, no index).
set -euxo pipefail
"${PYTHON}" -m pip install ./bindings/python -vv --no-deps --no-build-isolation
