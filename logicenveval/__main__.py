from logicenveval.cli import main

raise SystemExit(main())
