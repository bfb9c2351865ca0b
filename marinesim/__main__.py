from marinesim.cli import main

raise SystemExit(main())
