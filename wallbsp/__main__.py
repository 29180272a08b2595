import sys

from wallbsp.app.cli import main

sys.exit(main())
