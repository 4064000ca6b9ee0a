// SPDX-License-Identifier: GPL-2.0-or-later
// python_path.hpp - let the programs halcmd/halrun start (loadusr python3 comp.py,
// loadusr -W mycomp.py) import the Python 'hal' module that belongs to this
// halcmd: <dir of this executable>/../HAL_PYTHON_DIR, in a build tree and in an
// installed tree alike, is put first on PYTHONPATH when it exists.
#pragma once

namespace hal::halcmd {

void export_python_path();

}  // namespace hal::halcmd
