import sys

from simulator.commands.cli import main

sys.exit(main())
