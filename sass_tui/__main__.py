import sys

from sass_tui.cli import main

sys.exit(main())
