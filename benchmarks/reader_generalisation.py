"""How far the offline model's reading carries beyond the 25 built-in descriptions (issue 47).

Runs offline LogicEnvGen (the paper's default `--brief description`) on several sets of tasks and
prints LogCov / SceVR / FauDR for each, then per task:

- `built-in`: the 25 tasks of benchmark_data/tasks/;
- `reworded`: tests/data/reader_dev/tasks_reworded/ — rewordings of 12 built-in descriptions in
  other registers (terse, chatty, lists, questions, passive, British and American wording), same
  roles, trees, constraints and BTs as their originals (tools/build_reworded_tasks.py);
- `new`: tests/data/reader_dev/tasks_new/ — tasks written from scratch in rooms and with objects
  the built-in tasks do not use;
- `dev2 new`: tests/data/reader_dev2/tasks_new/ — the second development set (the first has been
  tuned on): new tasks in other registers (a voice transcript, a house-sitter's note, ...);
- `dev4 reworded` and `dev4 new`: tests/data/reader_dev4/ — the fourth development set, written
  once the first two were nearly saturated: one rewording each of 12 built-in descriptions, each
  in a register of its own (a note with typos, legalistic clauses, a Q&A, a transcript, ...), and
  six new tasks (an email above a quoted message, a child's dictated message, a landlord's
  inventory, a recipe, a note full of asides, a terse SMS). Tuned on, like the rows above;
- `held-out reworded` and `held-out new`: tests/data/reader_holdout/ — the held-out counterparts,
  rewordings of the 13 built-in descriptions the development set leaves out and new tasks in
  rooms and with objects neither the built-in tasks nor the development set use;
- `dev3 reworded` and `dev3 new`: tests/data/reader_dev3/ — written as a second unseen set after the
  development sets had been tuned on: one rewording each of 12 built-in descriptions, each in a
  register of its own (a voice transcript with a self-correction, a work order, a text thread, a
  FAQ, ...), and five new tasks in rooms and with objects none of the sets above use as theirs.
  Measured three times in aggregate only, then made a development set (the fourth session), when
  a fresh unseen set took its place;
- `dev5 reworded` and `dev5 new`: tests/data/reader_dev5/ — the fifth development set, for the
  next round of reader rules: one rewording each of 16 built-in descriptions (the 13 the first
  development set leaves out, so development covers all 25, and three more), each in a register
  no earlier development set's rewordings use (a decision table, pseudo-code, RFC-style MUST/MAY,
  a text-adventure, a flowchart, ...), and eight new tasks in rooms none of the sets above use (a
  coach's pep talk, an RA's email, an office memo, a church-hall rota, a chore chart, ...). Tuned
  on, like the development rows above;
- `dev6 reworded` and `dev6 new`: tests/data/reader_dev6/ — the sixth development set, written
  when every development row had reached 100 while the held-out sets' new tasks had not: one
  rewording each of 10 built-in descriptions, each in a register no earlier set's rewordings use
  (a landlady's house rules, a telegram, a game-show host, a wikiHow how-to, a Spanish-English
  text, ...), and ten new tasks in rooms none of the sets above use (a holiday let's welcome book,
  a stage manager's show report, a workshop sign in capitals, house-meeting minutes, a postcard, a
  rhyming note, a wedding run sheet, chat messages with *-corrections, ...). Tuned on, like the
  development rows above;
- `dev7 reworded` and `dev7 new`: tests/data/reader_dev7/ — the seventh development set, again
  weighted to new tasks: one rewording each of 6 built-in descriptions, each in a register no
  earlier set's rewordings use (a hotel turndown card, a screenplay, a babysitting job sheet, an
  Irish granny's note, a numbered social-media thread, a Scottish note), and ten new tasks in rooms
  none of the sets above use (a choir secretary's email, a yacht's logbook, a museum invigilator's
  checklist, a host's reply to a review, a camp counselor's list, a children's club rules, a yoga
  teacher's closing words, an allotment committee notice, a darkroom risk assessment, a caravan's
  visitors' book). Tuned on, like the development rows above;
- `dev8 reworded` and `dev8 new`: tests/data/reader_dev8/ — the eighth development set, written
  while the seventh was being tuned on: one rewording each of 6 built-in descriptions dev 7 left
  alone (a chef's list, a bullet journal, a dad's texts, a gardening column, a care plan, a note on
  a receipt), and ten new tasks in rooms none of the sets above use (a ferry steward's handover, a
  lighthouse keeper's diary, a neighbour's note, a caretaker's log, a pharmacy closing procedure, a
  bakery checklist, a studio booking email, a library porter's round, Singlish chat messages, a
  stables whiteboard). Measured before and after the sixth session's rules from dev 7, with
  nobody tuning on it, then tuned on;
- `dev9 reworded` and `dev9 new`: tests/data/reader_dev9/ — the ninth development set, written at
  the end of the sixth session: one rewording each of 4 built-in descriptions neither dev 7 nor
  dev 8 rewords (a captain's announcement, an audio-guide script, sat-nav directions, a Southern
  US note) and eight new tasks in rooms none of the sets above use (a gliding club's checklist, an
  aunty's WhatsApp message, a teacher's cover notes, a radio log, a Discord message, a phone
  message slip, a note written as a prescription, a pirate note). Unseen until measured;
- `dev10 reworded` and `dev10 new`: tests/data/reader_dev10/ — the tenth development set, written
  while dev 9 was being measured: one rewording each of 4 built-in descriptions neither dev 8 nor
  dev 9 rewords (a horoscope column, a TV weather forecast, a Cockney note with rhyming slang,
  Shakespearean English) and eight new tasks in rooms none of the sets above use (a bug report, a
  Jamaican Patois note, a sports commentary, a Taglish text, a bedtime story, a lab protocol, a
  surfer's note, an automated job email with unfilled mail-merge fields). Unseen until measured;
- `dev11 reworded` and `dev11 new`: tests/data/reader_dev11/ — the eleventh development set,
  written while dev 10 was being measured: one rewording each of 3 built-in descriptions neither
  dev 9 nor dev 10 rewords (a sequence of limericks, a vicar's sermon, a press release) and six new
  tasks in rooms none of the sets above use (a nature-documentary narration, a dungeon master's
  session notes, a Hinglish note, a YAML file, a sea shanty, a hard-boiled detective's monologue).
  Unseen until measured;
- `dev12 reworded` and `dev12 new`: tests/data/reader_dev12/ — the twelfth development set,
  written in registers of speech and personal writing after dev 11 was measured: one
  rewording each of 3 built-in descriptions (a love letter, an Italian-English voice message from
  a nonna, a Geordie note) and six new tasks in rooms none of the sets above use (a Denglisch chat,
  a radio phone-in transcript, a teenager's diary, an oral-history interview, a moving-out letter,
  a "clean with me" vlog transcript). Unseen until measured;
- `dev13 reworded` and `dev13 new`: tests/data/reader_dev13/ — the thirteenth development set,
  written beside the twelfth in registers of documents, forms and genre writing: one rewording each
  of 3 built-in descriptions (a sequence of haiku, a job advertisement, a board-game rulebook) and
  six new tasks in rooms none of the sets above use (a knitting pattern, patent claims, a
  choose-your-own-adventure gamebook, a software changelog, a mock royal proclamation, an
  encyclopedia article). Unseen until measured;
- `dev14 reworded` and `dev14 new`: tests/data/reader_dev14/ — the fourteenth development set,
  written after dev 12 and 13 in registers of neither family (performance, instructions for
  machines and games, quizzes, signage, lists of other kinds, non-native English): one rewording
  each of 3 built-in descriptions (a pantomime script, a multiple-choice quiz, a French speaker's
  English) and six new tasks in rooms none of the sets above use (a stand-up comedy set, IFTTT-style
  applets, labels stuck on the objects, a Russian speaker's English email, a clickbait listicle, a
  video-game quest log). Unseen until measured;
- `dev15 reworded` and `dev15 new`: tests/data/reader_dev15/ — the fifteenth development set,
  written after dev 14 in registers of workplace and trade writing, messaging formats, writing of
  another period, speech written down and machine translation: one rewording each of 3 built-in
  descriptions (a forum post quoting earlier posts, a recipe card, a police sergeant's briefing)
  and six new tasks in rooms none of the sets above use (a plumber's job ticket, an email reply
  chain with quoted lines, a Victorian household manual, a 1950s advertisement, a child's dictation
  written down by her father, a careless machine translation from Japanese). Unseen until measured;
- `dev16 reworded` and `dev16 new`: tests/data/reader_dev16/ — the sixteenth development set,
  written after dev 15 in registers no set used (documents of a tenancy, school and home life,
  voices other than the writer's own, non-native English): one rewording each of 3 built-in
  descriptions (a mission-control countdown, a Dutch speaker's English, a house-clearance auction
  catalogue) and six new tasks in rooms none of the sets above use (a landlord's check-in
  inventory, a dream journal, a teacher's instructions to pupils, a landlord's letter in a
  deposit dispute, a Brazilian Portuguese speaker's English, a letter in the voice of the family
  cat). Unseen until measured;
- `dev17 reworded` and `dev17 new`: tests/data/reader_dev17/ — the seventeenth development set,
  written after dev 16, beside dev 18, in registers of spoken, broadcast, official and commercial
  writing and the English of a Spanish speaker: one rewording each of 3 built-in descriptions (a
  TV shopping-channel segment, a parliamentary question time in Hansard, a radio news bulletin)
  and six new tasks in rooms none of the sets above use (courtroom testimony, an insurance claim
  form, a building manager's notice to residents, a holiday cottage's support chatbot log, a
  hotel's product-recall notice, a Spanish speaker's note). Fresh (`FRESH`) until measured four
  times (tenth session, start of the eleventh), then a development set;
- `dev18 reworded` and `dev18 new`: tests/data/reader_dev18/ — the eighteenth development set,
  written beside dev 17 (each in its own family of registers) in personal, literary and digital
  registers no set used: one rewording each of 3 built-in descriptions (a letter to one's future
  self, a Homeric epic pastiche, a sonnet) and six new tasks in rooms
  none of the sets above use (a Korean speaker's KakaoTalk message, a Regency-novel pastiche, a
  Gothic tale, a speech-to-text dictation, an Instagram caption, a science-fiction captain's log).
  Fresh until measured four times (tenth session, start of the eleventh), then a development set;
- `dev19 reworded` and `dev19 new`: tests/data/reader_dev19/ — the nineteenth development set,
  written in the eleventh session (beside dev 20, each in its own family of registers) in
  registers of work, service and the trades and of science and technology, and the English of a
  Mandarin Chinese speaker: one rewording each of 3 built-in descriptions (a chemical safety data
  sheet, a call-centre agent's script, a scientific paper's Materials and Methods section) and six
  new tasks in rooms none of the sets above use (a vet nurse's SBAR handover, a builder's
  snagging list, an on-call runbook, a mathematician's claim and proof, an ecologist's field
  record sheet, a Mandarin speaker's note). Fresh (`FRESH`) until measured three times (eleventh
  session), then a development set;
- `dev20 reworded` and `dev20 new`: tests/data/reader_dev20/ — the twentieth development set,
  written in the eleventh session beside dev 19 (each in its own family of registers) in family,
  community, leisure and entertainment registers no set used and the English of a Greek speaker:
  one rewording each of 3 built-in descriptions (a film-trailer voice-over, a square-dance
  caller's calls, a Christmas round-robin letter) and six new tasks in rooms none of the sets
  above use (a Greek grandfather's note, a Scout badge card, a fan-fiction chapter, a podcast's
  opening housekeeping, a bingo caller's patter, a best man's speech). Fresh (`FRESH`) until
  measured three times (eleventh session), then a development set;
- `dev21 reworded` and `dev21 new`: tests/data/reader_dev21/ — the twenty-first development set,
  written in the twelfth session (beside dev 22, each in its own family of registers) in
  registers of sport, travel, health and education no set used and the English of a Polish
  speaker: one rewording each of 3 built-in descriptions (a tour operator's day itinerary, a
  medicine's patient information leaflet, a primary school's end-of-term report card) and six new
  tasks in rooms none of the sets above use (a swimming coach's session sheet, a walking
  guidebook's bothy entry, a physiotherapist's home exercise programme, a language lab induction
  worksheet for Year 7, a Polish agritourism host's note, a golf club's scorecard with local
  rules). Fresh (`FRESH`) until measured three times (twelfth session), then a development set;
- `dev22 reworded` and `dev22 new`: tests/data/reader_dev22/ — the twenty-second development set,
  written in the twelfth session (beside dev 21, each in its own family of registers) in
  registers of law, religion, history, the arts and the old-fashioned no set used and the English
  of a Polish speaker: one rewording each of 3 built-in descriptions (an Act of Parliament, a
  medieval chronicle's annal, an opera libretto) and six new tasks in rooms none of the sets above
  use (a mock last will and testament, a monastic rule for a refectory, a wartime public
  information leaflet, an artist's instruction pieces, a Polish landlady's note, an old-fashioned
  reading primer). Fresh (`FRESH`) until measured three times (twelfth session), then a
  development set;
- `dev23 reworded` and `dev23 new`: tests/data/reader_dev23/ — the twenty-third development set,
  written in the thirteenth session (beside dev 24, each in its own family of registers) in
  registers of food and drink, farming and gardening, animals, nature and the weather no set used
  and the English of a Swahili speaker: one rewording each of 3 built-in descriptions (an
  almanac page, a restaurant review, a field guide) and six new tasks in rooms none of the sets
  above use (a beekeeper's record, a seed packet, a tasting note, a dog walker's handover, a
  shipping-forecast pastiche, a Swahili speaker's SMS). Fresh (`FRESH`) until measured three
  times (fourteenth session), then a development set;
- `dev24 reworded` and `dev24 new`: tests/data/reader_dev24/ — the twenty-fourth development set,
  written in the thirteenth session (beside dev 23) in registers of commerce, the media, the
  internet and officialdom no set used and the English of a Swedish speaker: one rewording each
  of 3 built-in descriptions (a cleaning quote, a GOV.UK-style page, TV listings) and six new
  tasks in rooms none of the sets above use (a marketplace listing, a product review, a
  corrections column, a planning decision notice, an app's e-mail digest, a Swedish speaker's
  note). Fresh (`FRESH`) until measured three times (fourteenth session), then a
  development set;
- `dev25 reworded` and `dev25 new`: tests/data/reader_dev25/ — the twenty-fifth development set,
  written in the fourteenth session (beside dev 26, each in its own family of registers) in
  registers of sport, games and hobbies, travel and transport no set used and the English of a
  Vietnamese speaker: one rewording each of 3 built-in descriptions (a driving examiner's
  instructions, a darts MC's calling, a climbing wall's safety briefing) and six new tasks in
  rooms none of the sets above use (a karate club's dojo etiquette sheet, a railway
  engineering-works notice, a cycling club's ride sheet, a chess arbiter's announcement, an
  airline boarding pass, a Vietnamese aunt's note). Fresh (`FRESH`) until measured three times
  (fourteenth and fifteenth sessions), then a development set;
- `dev26 reworded` and `dev26 new`: tests/data/reader_dev26/ — the twenty-sixth development set,
  written in the fourteenth session (beside dev 25, each in its own family of registers) in
  registers of science, medicine, engineering and the trades no set used and the English of a
  Finnish speaker: one rewording each of 3 built-in descriptions (a surgical safety checklist, a
  garage's vehicle health check, a clinical trial protocol synopsis) and six new tasks in rooms
  none of the sets above use (a GP's referral letter, an electrical installation condition
  report's observations, a service manual's troubleshooting table, a peer reviewer's report, a
  maintenance task card, a Finnish cottage owner's note about the sauna). Fresh (`FRESH`) until
  measured three times (fourteenth and fifteenth sessions), then a development set;
- `dev27 reworded` and `dev27 new`: tests/data/reader_dev27/ — the twenty-seventh development set,
  written in the fifteenth session (beside dev 28, each in its own family of registers) in
  registers of law, finance, insurance, government forms and religious life no set used and the
  English of a Turkish speaker: one rewording each of 3 built-in descriptions (a family court's
  consent order, a company's notice of annual general meeting, a catechism) and six new tasks in
  rooms none of the sets above use (a solicitor's letter before action, a building society's
  account statement, an insurance product information document, an application form for a
  weekend pass, a chapel's order of service, a Turkish host's note about the guest room). Fresh
  (`FRESH`) until measured five times (fifteenth session), then a development set;
- `dev28 reworded` and `dev28 new`: tests/data/reader_dev28/ — the twenty-eighth development set,
  written in the fifteenth session (beside dev 27, each in its own family of registers) in
  registers of childcare, elder care, hospitality, retail and farming no set used and the English
  of a Hungarian speaker: one rewording each of 3 built-in descriptions (a telecare operator's
  call-out sheet, a garden centre's aftercare job card, a farm volunteer's morning card) and six
  new tasks in rooms none of the sets above use (a day nursery's daily diary, a home care
  agency's daily visit record, a pub's taproom close-down card, a store chain's weekly store
  communication, a dairy farm's relief milker notes, a Hungarian flatmate's note). Fresh
  (`FRESH`) until measured five times (fifteenth session), then a development set;
- `dev29 reworded` and `dev29 new`: tests/data/reader_dev29/ — the twenty-ninth development set,
  written in the fifteenth session (beside dev 30, each in its own family of registers) in
  registers of the arts, music, theatre, crafts and museums no set used and the English of an
  Arabic speaker: one rewording each of 3 built-in descriptions (a radio play's script, a
  quilting pattern, a concert programme note) and six new tasks in rooms none of the sets above
  use (a stage manager's rehearsal report, a band's set list, a life-drawing class's session plan,
  a historic house museum's housekeeping schedule, a pottery studio's members' notice, an Arabic
  speaker's note about the majlis). Fresh (`FRESH`) until measured six times (sixteenth session),
  then a development set;
- `dev30 reworded` and `dev30 new`: tests/data/reader_dev30/ — the thirtieth development set,
  written in the fifteenth session (beside dev 29, each in its own family of registers) in
  registers of emergency services, the armed forces, aviation, shipping and security no set used
  and the English of a Romanian speaker: one rewording each of 3 built-in descriptions (a cargo
  superintendent's stowage instruction, a QRH non-normal checklist, a control room's protocol
  card) and six new tasks in rooms none of the sets above use (a fire station's watch handover
  log, a battalion's Part One Orders, a flying club's crew-room NOTAM, a ship master's night order
  book, a guarding company's assignment instructions, a Romanian neighbour's note). Fresh
  (`FRESH`) until measured six times (sixteenth session), then a development set;
- `dev31 reworded` and `dev31 new`: tests/data/reader_dev31/ — the thirty-first development set,
  written in the sixteenth session (beside dev 32, each in its own family of registers) in
  registers of laboratories and the sciences, construction, logistics, property and video gaming
  no set used and the English of a Persian (Farsi) speaker: one rewording each of 3 built-in
  descriptions (a courier's run sheet, a speedrunner's route notes, an NBS-style building
  specification) and six new tasks in rooms none of the sets above use (a peer reviewer's report,
  a builder's site diary, a warehouse pick list, a surveyor's home survey report, a game's patch
  notes, a Persian aunt's note). Fresh (`FRESH`) until measured seven times (seventeenth session),
  then a development set;
- `dev32 reworded` and `dev32 new`: tests/data/reader_dev32/ — the thirty-second development set,
  written in the sixteenth session (beside dev 31, each in its own family of registers) in
  registers of utilities and energy, broadcasting and telecoms, zoos and wildlife parks, surveying
  and mapping, and beekeeping and brewing no set used and the English of an Indonesian speaker:
  one rewording each of 3 built-in descriptions (a beekeeping association's jobs-for-the-month
  column, a live television running order, a water company's notice to a customer) and six new
  tasks in rooms none of the sets above use (an electricity network's planned power-cut notice, a
  broadband engineer's appointment confirmation, a zoo keeper's daily round sheet, a land
  surveyor's field notes, a home brewer's batch log, an Indonesian host's note about the ruang
  tamu). Fresh (`FRESH`) until measured seven times (seventeenth session), then a development
  set;
- `dev33 reworded` and `dev33 new`: tests/data/reader_dev33/ — the thirty-third development set,
  written in the seventeenth session (beside dev 34, each in its own family of registers) in
  registers of politics and elections, journalism and magazines, fashion and textiles, astronomy
  and space flight, and software operations no set used and the English of a Ukrainian speaker:
  one rewording each of 3 built-in descriptions (an incident postmortem, a news website's live
  blog, an amateur astronomer's observing plan) and six new tasks in rooms none of the sets above
  use (a candidate's election leaflet, an interiors magazine's room-of-the-month feature, a
  fashion tech pack, a space station's onboard short-term plan, a pull request's code review, a
  Ukrainian grandmother's note about the hostynna). Fresh (`FRESH`) until measured eight times
  (eighteenth session), then a development set;
- `dev34 reworded` and `dev34 new`: tests/data/reader_dev34/ — the thirty-fourth development set,
  written in the seventeenth session (beside dev 33, each in its own family of registers) in
  registers of mining and quarrying, forestry and fisheries, libraries and archives, advertising
  and marketing, and film and television production no set used and the English of a Thai
  speaker: one rewording each of 3 built-in descriptions (a costume department's wardrobe and
  laundry notes, a tree nursery's daily operations worksheet, a library's shelving guide for
  volunteers) and six new tasks in rooms none of the sets above use (a pit deputy's statutory
  inspection report, a fishing skipper's standing orders, an archive's catalogue entry, an
  advertising agency's creative brief, a location call sheet, a Thai house-sitter's note about the
  sala). Fresh (`FRESH`) until measured eight times (eighteenth session), then a development
  set;
- `dev35 reworded` and `dev35 new`: tests/data/reader_dev35/ — the thirty-fifth development set,
  written in the eighteenth session (beside dev 36, each in its own family of registers) in
  registers of cartography and orienteering, perfumery and cosmetics, wilderness guiding and
  camping, crossword setting and word games, and auditing and tax compliance no set used and the
  English of a Czech speaker: one rewording each of 3 built-in descriptions (an orienteering
  course's notes, a cosmetics carton's directions for use, a tax authority's compliance check
  letter) and six new tasks in rooms none of the sets above use (a surveyor's map sheet with its
  legend, a perfumer's formula card, a mountain leader's camp briefing, a prize cryptic crossword
  with its solutions, an internal audit report, a Czech speaker's note about the chalupa). Fresh
  (`FRESH`) until measured ten times (nineteenth session), then a development set;
- `dev36 reworded` and `dev36 new`: tests/data/reader_dev36/ — the thirty-sixth development set,
  written in the eighteenth session (beside dev 35, each in its own family of registers) in
  registers of tram and bus transit operations, ballet and dance, postal and parcel services,
  circus and stage magic, and locksmithing and home security no set used and the English of a
  Bengali speaker: one rewording each of 3 built-in descriptions (a line-dance step sheet, a
  circus ring crew's cue sheet, a bus driver's duty card) and six new
  tasks in rooms none of the sets above use (a tram depot's notice to drivers, a ballet
  mistress's rehearsal notes, a sub-postmaster's instructions to a relief, a stage magician's
  routine sheet, a locksmith's home security survey, a Bengali aunt's note about the shobar
  ghor). Fresh (`FRESH`) until measured ten times (nineteenth
  session), then a development set;
- `dev37 reworded` and `dev37 new`: tests/data/reader_dev37/ — the thirty-seventh development set,
  written in the nineteenth session (beside dev 38, each in its own family of registers) in
  registers of glassblowing and glass studios, falconry and bird handling, archaeological
  excavation, weather stations and meteorology, and cricket scoring and umpiring no set used and
  the English of a Yoruba speaker: one rewording each of 3 built-in descriptions (the Laws of
  Cricket as a household code, an archaeological Written Scheme of Investigation, a glassblowing
  gaffer's piece plan) and six new tasks in rooms none of the sets above use (a glass studio's
  hot-shop shutdown card, a falconer's mews notes, an excavation's context sheet, a
  climatological station's observer's daily register, a cricket scorer's close-of-play notes, a
  Yoruba mother's note about the iyara). Fresh (`FRESH`) until measured ten times (twentieth
  session), then a development set;
- `dev38 reworded` and `dev38 new`: tests/data/reader_dev38/ — the thirty-eighth development set,
  written in the nineteenth session (beside dev 37, each in its own family of registers) in
  registers of watch and clock repair, scuba diving and dive centres, air traffic control,
  bookbinding and letterpress printing, and tailoring and dressmaking no set used and the English
  of a Hebrew speaker: one rewording each of 3 built-in descriptions (a dive guide's site
  briefing, a mechanical watch's instructions for use, an aerodrome's ATIS broadcast) and six new
  tasks in rooms none of the sets above use (a watchmaker's repair job ticket, a dive centre's
  closing checklist, a tower controller's position relief briefing, a letterpress job docket, a
  tailor's alteration ticket, an Israeli grandmother's note about the salon). Fresh (`FRESH`)
  until measured ten times (twentieth session), then a development set;
- `dev39 reworded` and `dev39 new`: tests/data/reader_dev39/ — the thirty-ninth development set,
  written in the twenty-first session (beside dev 40, each in its own family of registers) in
  registers of veterinary practice, church bell-ringing, chess arbitration, pharmacy and livery
  yards no set used and the English of a Malay speaker: one rewording each of 3 built-in
  descriptions (a change-ringing method sheet, a pharmacy dispensing label, a dressage test sheet)
  and six new tasks in rooms none of the sets above use (a vet nurse's dog-ward close-down sheet,
  a tower captain's practice notes, a chess arbiter's venue checklist, a pharmacist's locum
  handover, a livery yard's holiday cover sheet, a Malay auntie's note about the dapur). Fresh
  (`FRESH`) until measured ten times (the twenty-third session, after its second merge), then a
  development set;
- `dev40 reworded` and `dev40 new`: tests/data/reader_dev40/ — the fortieth development set,
  written in the twenty-first session (beside dev 39, each in its own family of registers) in
  registers of railway signalling, barbering, rowing, wine service and motor racing no set used
  and the English of a Tamil speaker: one rewording each of 3 built-in descriptions (a salon
  training card, a module of a railway rule book, a pit-stop procedure) and six new tasks in
  rooms none of the sets above use (a signaller's handover, a barber's closing routine, a rowing
  club boatman's notes, a cellar master's list, a pit garage's close-down sheet, a Tamil
  landlord's note about the upstairs portion). Fresh (`FRESH`) until measured ten times (the
  twenty-third session, after its first merge), then a development set;
- `dev41 reworded` and `dev41 new`: tests/data/reader_dev41/ — the forty-first development set,
  written in the twenty-third session (beside dev 42, each in its own family of registers, by
  helpers who never read or ran the reader) in registers of outdoor and animal work no set used
  and the English of a Vietnamese speaker: one rewording each of 3 built-in descriptions (a
  pheasant shoot headkeeper's word to the beaters, a countryside ranger service's volunteer task
  sheet, a wildlife rescue's foster care sheet) and six new tasks in rooms none of the sets above
  use (a lido lifeguard room's close-down sheet, a ski patrol hut's closing notes, a boarding
  cattery's weekend cover notes, a shepherd's notes for the night lamber, a canal's volunteer lock
  keepers' end-of-shift notice, a Vietnamese neighbour's note about her hens). Fresh (`FRESH`)
  until measured ten times (the twenty-fifth session, after its fifth merge), then a development
  set;
- `dev42 reworded` and `dev42 new`: tests/data/reader_dev42/ — the forty-second development set,
  written in the twenty-third session beside dev 41 in registers of technical and institutional
  work no set used and the English of a Turkish speaker: one rewording each of 3 built-in
  descriptions (a permit to work, a records retention and disposal schedule, a standard operating
  procedure) and six new tasks in rooms none of the sets above use (a data-centre operations shift
  log, a university cleanroom's gowning notice, a hospital porters' note for nights, a Crown Court
  usher's notes for a relief usher, a register office's ceremony room clear-down sheet, a Turkish
  landlady's note to her tenant). Fresh (`FRESH`) until measured ten times (the twenty-fifth
  session, after its fifth merge), then a development set;
- `dev43 reworded` and `dev43 new`: tests/data/reader_dev43/ — the forty-third development set,
  written in the twenty-fifth session (beside dev 44, each in its own family of registers, by
  helpers who never read or ran the reader) in registers of care and service work in other
  people's places no set used and the English of a Nepali speaker: one rewording each of 3 built-in
  descriptions (a disabled employer's guide for her personal assistants, an au pair handbook's
  page, a home-from-hospital volunteer's task card) and six new tasks in rooms none of the sets
  above use (a district nurse's continuation notes, a chapel of rest viewing checklist, a removal
  firm's pack and load sheet, a hotel's in-room dining collection card, a night nanny's log, a
  Nepali live-in carer's note). Fresh (`FRESH`) until measured ten times (the twenty-sixth session,
  after its first merge), then a development set;
- `dev44 reworded` and `dev44 new`: tests/data/reader_dev44/ — the forty-fourth development set,
  written in the twenty-fifth session beside dev 43 in registers of making and repairing things no
  set used and the English of a Nepali speaker (both helpers chose Nepali, each unaware of the
  other): one rewording each of 3 built-in descriptions (a screen-print shop's end-of-run
  checklist, a dolls' hospital's discharge and aftercare note, flat-pack furniture assembly
  instructions) and six new tasks in rooms none of the sets above use (a bicycle workshop's job
  card, a piano tuner's visit notes, a boatyard's winter lay-up list, a blacksmith's end-of-day
  card, a repair café's closing sheet, a Nepali flatmate's note). Fresh (`FRESH`) until measured
  ten times (the twenty-sixth session, after its first merge), then a development set;
- `dev45 reworded` and `dev45 new`: tests/data/reader_dev45/ — the forty-fifth development set,
  written in the twenty-sixth session (beside dev 46, each in its own family of registers, by
  helpers who never read or ran the reader) in registers of transport and travel work no set used
  and the English of a Maltese speaker: one rewording each of 3 built-in descriptions (a sleeper
  train host's cabin preparation card, a removal firm's evening-before e-mail, a coach driver's
  walkaround check sheet as a bedtime house check) and six new tasks in rooms none of the sets above
  use (a Gozo ferry bosun's note for the crew mess, a bus garage controller's handover log, a
  railway station's closing-down book, a marina berthing master's cover e-mail, a removal crew's
  group chat, a coach tour manager's departure letter). Fresh (`FRESH`) until measured ten times
  (the twenty-sixth session), then a development set;
- `dev46 reworded` and `dev46 new`: tests/data/reader_dev46/ — the forty-sixth development set,
  written in the twenty-sixth session beside dev 45 in registers of education and children no set
  used and the English of a Georgian speaker: one rewording each of 3 built-in descriptions (a Year
  1 home challenge card, a boarding house matron's laundry room notice, Montessori practical-life
  work cards) and six new tasks in rooms none of the sets above use (a day nursery's toddler room
  closing handover, a school site manager's lettings note, a Scout quartermaster's camp returns
  note, a children's library's Saturday close, a swimming club's gala pack-down sheet, a Georgian
  piano teacher's note). Fresh (`FRESH`) until measured ten times (the twenty-sixth session), then
  a development set;
- `dev47 reworded` and `dev47 new`: tests/data/reader_dev47/ — the forty-seventh development set,
  written in the twenty-seventh session (beside dev 48, by helpers who never read or ran the
  reader) in registers of emergency services, security and public safety work and the English of a
  Haitian Creole speaker: one rewording each of 3 built-in descriptions (a fire incident
  commander's radio tasking, a security company's keyholding site instructions, a search and rescue
  team's task assignment sheet) and six new tasks in rooms none of the sets above use (a lifeboat
  station helm's crew-room notes, a condominium security officer's relief note, a mountain rescue
  kit room card, a coastwatch station log, a police front counter's close-down notes, an ambulance
  station's day-room card). Fresh (`FRESH`) until measured ten times (the twenty-eighth session),
  then a development set;
- `dev48 reworded` and `dev48 new`: tests/data/reader_dev48/ — the forty-eighth development set,
  written in the twenty-seventh session beside dev 47 in registers of retail, markets and shop work
  and the English of a Bosnian speaker: one rewording each of 3 built-in descriptions (a furniture
  store's room-set display standards card, a supermarket's tannoy announcement, a shop's returns
  and exchanges policy notice) and six new tasks in rooms none of the sets above use (a charity
  shop's sorting room day book, a florist's order book, a second-hand bookseller's letter, a
  hardware shop owner's closing note, a market trader's texts, a bridal boutique's stylist
  handbook). Fresh (`FRESH`) until measured ten times (the twenty-eighth session), then a
  development set;
- `dev49 reworded` and `dev49 new`: tests/data/reader_dev49/ — the forty-ninth development set,
  written in the twenty-eighth session (beside dev 50, by helpers who never read or ran the
  reader) in registers of food and drink production work and the English of a Basque speaker: one
  rewording each of 3 built-in descriptions (a vineyard winery's cellar work order, a chilled
  desserts factory's hygiene lobby procedure, a confectionery factory's line clearance checklist)
  and six new tasks in rooms none of the sets above use (a microbrewery head brewer's handover, a
  Basque cider maker's note, a coffee roastery's close list, a smokehouse day book, a gin
  distillery's Friday close e-mail, a farmhouse cheesemaker's make sheet). Fresh (`FRESH`) until
  measured ten times (the twenty-ninth session), then a development set;
- `dev50 reworded` and `dev50 new`: tests/data/reader_dev50/ — the fiftieth development set,
  written in the twenty-eighth session beside dev 49 in registers of religious, funeral and
  community caretaking work and the English of a Punjabi speaker: one rewording each of 3 built-in
  descriptions (a church good neighbours scheme's visit card, a Salvation Army lifehouse's room
  changeover sheet, an almshouse warden's weekly check sheet) and six new tasks in rooms none of the
  sets above use (a church verger's relief notes, a mosque caretaker's note, a synagogue caretaker's
  Friday note, a crematorium chapel attendants' card, a Quaker meeting house warden's notes, a
  gurdwara langar kitchen note). Fresh (`FRESH`) until measured ten times (the twenty-ninth
  session), then a development set;
- `dev51 reworded` and `dev51 new`: tests/data/reader_dev51/ — the fifty-first development set,
  written in the twenty-ninth session (beside dev 52, by helpers who never read or ran the reader)
  in registers of sports ground, stable and leisure facility work and the English of an Icelandic
  speaker: one rewording each of 3 built-in descriptions (a football ground safety officer's
  post-match sweep briefing, a parkrun run director's pre-run briefing, a racing yard's evening
  stables round card) and six new tasks in rooms none of the sets above use (an ice rink's skate
  hire close-down notes, a bowls club's pavilion lock-up card, a pool plant operator's log, a
  racecourse head valet's notes, a dry ski slope's instructors' hut list, an Icelandic horse stud's
  foaling night-watch note). Fresh (`FRESH`) until measured ten times (the twenty-ninth session,
  after its tenth reader commit), then a development set;
- `dev52 reworded` and `dev52 new`: tests/data/reader_dev52/ — the fifty-second development set,
  written in the twenty-ninth session beside dev 51 in registers of laboratory and collections work
  and the English of a Lithuanian speaker: one rewording each of 3 built-in descriptions (a
  museum's pest management inspection record, a university animal facility's husbandry check
  sheet, a museum registrar's object location audit) and six new tasks in rooms none of the sets
  above use (a herbarium curator's note, an aquarium aquarist's handover, a seed bank technician's
  note, a teaching lab's end-of-practical checklist, a spirit collection manager's e-mail, a rock
  preparation room technician's notes). Fresh (`FRESH`) until measured ten times (the
  twenty-ninth session, after its tenth reader commit), then a development set;
- `dev53 reworded` and `dev53 new`: tests/data/reader_dev53/ — the fifty-third development set,
  written in the twenty-ninth session (beside dev 54, by helpers who never read or ran the reader)
  in registers of utilities and infrastructure work and the English of a Telugu speaker: one
  rewording each of 3 built-in descriptions (an electricity control engineer's switching
  programme, a wind turbine technician's service checklist, a gas emergency call handler's script)
  and six new tasks in rooms none of the sets above use (a water treatment works' shift handover, a
  substation log book, a pumping station visit e-mail, a telephone exchange night note, a reservoir
  keeper's weekend notes, a flood barrier shift log). Fresh (`FRESH`) until measured ten times (the
  thirtieth session, after its ninth reader commit), then a development set;
- `dev54 reworded` and `dev54 new`: tests/data/reader_dev54/ — the fifty-fourth development set,
  written in the twenty-ninth session beside dev 53 in registers of arts and crafts workshop work
  and the English of an Odia speaker: one rewording each of 3 built-in descriptions (a natural-dye
  studio's recipe card, an etching studio's clean-down card, a picture framer's work ticket) and six
  new tasks in rooms none of the sets above use (a filigree jeweller's note, a stained glass class
  card, a weaving studio's loom hire page, a papermaker's intern notes, a woodturners' club card, a
  basketmaker's texts). Fresh (`FRESH`) until measured ten times (the thirtieth session, after
  its ninth reader commit), then a development set;
- `dev55 reworded` and `dev55 new`: tests/data/reader_dev55/ — the fifty-fifth development set,
  written in the thirtieth session (beside dev 56, by helpers who never read or ran the reader) in
  registers of hospitality and events work and the English of a Bulgarian speaker: one rewording
  each of 3 built-in descriptions (a hotel housekeeping room inspection sheet, a bed-and-breakfast's
  lock-up card, a private caterer's clear-down sheet) and six new tasks in rooms none of the sets
  above use (a conference breakout room changeover sheet, a banqueting hall function sheet, a
  theatre circle bar's close notes, a youth hostel reception handover book, a campsite shop note, a
  wedding venue's bridal suite reset card). Fresh (`FRESH`) until measured ten times (the
  thirtieth session, the one it was written in, after its twelfth reader commit), then a
  development set;
- `dev56 reworded` and `dev56 new`: tests/data/reader_dev56/ — the fifty-sixth development set,
  written in the thirtieth session beside dev 55 in registers of farming, forestry and growing work
  and the English of a Shona speaker: one rewording each of 3 built-in descriptions (an
  agronomist's crop walking report, a farm assurance inspection checklist, a forest harvesting site
  plan) and six new tasks in rooms none of the sets above use (a tree surgery yard's saw shop notes,
  an oast house drier's night notes, a clearfell site's welfare cabin sheet, a mushroom farm packing
  room note, a flower farm's sorting shed note, a Christmas tree farm's netting shed card). Fresh
  (`FRESH`) until measured ten times (the thirtieth session, after its twelfth reader commit),
  then a development set;
- `dev57 reworded` and `dev57 new`: tests/data/reader_dev57/ — the fifty-seventh development set,
  written in the thirty-first session (beside dev 58, by helpers who never read or ran the reader)
  in registers of health and care work and the English of a Malayalam speaker: one rewording each
  of 3 built-in descriptions (a children's ward play specialist's note, a care home's en-suite check
  card, a vet nurse's in-patient care sheet) and six new tasks in rooms none of the sets above use
  (a dental decontamination room sheet, a care home assisted bathroom card, an endoscopy recovery
  checklist, a dementia day centre activities room note, a hydrotherapy pool close-down, a birth
  room turnaround card). Fresh (`FRESH`) until measured ten times, then a development set;
- `dev58 reworded` and `dev58 new`: tests/data/reader_dev58/ — the fifty-eighth development set,
  written in the thirty-first session beside dev 57 in registers of office, legal and
  administrative work and the English of a Sinhala speaker: one rewording each of 3 built-in
  descriptions (an office's clear desk policy, a house-sitting agreement's schedule, a service
  level agreement's schedule) and six new tasks in rooms none of the sets above use (an accountancy
  payroll room note, a solicitors' partners' room handover, a records office search room closing
  procedure, a polling station's close-of-poll notes, an advice centre waiting room's notes, a call
  centre training room note). Fresh (`FRESH`) until measured ten times, then a development set;
- `held-out2 reworded` and `held-out2 new`: tests/data/reader_holdout2/ — the second held-out set,
  written after all of the above without reading the reader: one rewording each of 12 built-in
  descriptions and eight new tasks, each in a register no earlier set used, the new tasks in rooms
  and with objects none of the sets above use. Aggregate only, like the held-out rows.

The development sets were written before the offline model's reader was changed and were never
run through it while being written; the reader is developed against them, with no rule keyed on
one of their phrases. The held-out sets are stricter still: the reader is tuned on the development
set and the built-in tasks only, and those who change it never read or run the held-out texts, so
only the held-out rows say whether its rules carry to text nobody tuned them on. A further row, `built-in
(reworded originals)`, restricts the built-in row to the 12 tasks the reworded set rewords, for a
like-for-like gap.

Every run is computed afresh (`fresh=True`: a stored unit is never reused, since the run's
fingerprint does not cover the reader's code) with the offline model's reply cache off.

    python benchmarks/reader_generalisation.py            # every row (~3-6 min on 2 cores)
    python benchmarks/reader_generalisation.py --smoke    # two tasks per set (~1 min)
    python benchmarks/reader_generalisation.py --why      # and why each task lost environments
    python benchmarks/reader_generalisation.py --dev-only # without the held-out sets (for tuning)

The held-out rows show their aggregate only: no per-task line, no `--why` reason and no
per-task entry in `--json`, so running the benchmark gives whoever tunes the reader nothing to tune
on (they run `--dev-only`, which skips those sets altogether).

Before a reader rule is merged, check it per task on every development set, not only the one it
was written for (a rule too wide shows as a task of another set falling):

    python benchmarks/reader_generalisation.py --dev-only --json before.json   # on main
    python benchmarks/reader_generalisation.py --dev-only --compare before.json # with the rule

`--dev-only` also leaves out the fresh development sets nobody has tuned on yet (`FRESH`: the
sets written in a session, until measured: now dev 57 and dev 58; dev 25 and
dev 26 left it in the fifteenth session after their third measurement, dev 27 and dev 28 after their
fifth, dev 29 and dev 30 in the sixteenth after their sixth, dev 31 and dev 32 in the
seventeenth after their seventh, dev 33 and dev 34 in the eighteenth after their eighth, dev 35 and dev 36 in the
nineteenth after their tenth, dev 37 and dev 38 in the twentieth after their tenth, and dev 40 in the
twenty-third after its tenth, dev 39 after its tenth in the same session, dev 41 and dev 42 in the
twenty-fifth after their tenth, dev 43 and dev 44 in the twenty-sixth after their tenth, dev 45 and
dev 46 in the twenty-seventh after their tenth, dev 47 and dev 48 in the twenty-eighth after
their tenth, dev 49 and dev 50 in the twenty-ninth after their tenth, dev 51 and dev 52,
written in the same session, after their tenth, dev 53 and dev 54 in the thirtieth after
their tenth, and dev 55 and dev 56, written in the same session, after their tenth), so a tuner's runs
never show them; `--dev-only --fresh` keeps them, to measure them. `--skip 'dev9 reworded,dev9 new'` leaves any other rows' sets out as well.
`--only 'held-out reworded,held-out2 reworded'` measures those rows alone: to find which commit of a
merged branch moved an unseen row, run it at each commit (every tree has those rows, where a skip
list would name sets an older tree lacks).

`--placements` measures instead the reader's recall of stated placements, without running a
generator: per row, the share of the tasks' stated placement facts (each constraint whose `fact` is
one `on(x, y)` or `inside(x, y)`, asserted by its `says` words) that the offline reader states as
placements (`offline.placement.described_placements`) when given the task's own roles, so that the
figure measures the placement stage, not the naming. With `--why` it lists every missed fact (task,
fact, its `says`) of a development row; a held-out or fresh row shows its share only.

    python benchmarks/reader_generalisation.py --dev-only --placements --why   # seconds

`--losses` runs the rows as usual but prints, instead of the per-task lines, per row how many of
its tasks lose in each **loss class** (a task may count in several), so that the stage that loses
on unseen text can be named without seeing any unseen text or per-task figure. The classes come
from what the run records: a message row of `MESSAGE_CLASSES` (failures of `results["failures"]`,
problems, violations and the correct BT's verdict of `samples.jsonl`; first matching row wins), or
a figure test of `METRIC_CLASSES` on the task's metrics:

- `unbound role`: a GT role no object binds (a naming loss: a thing named as the wrong kind or not
  at all);
- `ill-formed: no leaf` / `ill-formed: other`: an environment ill-formed otherwise (a variable
  reaching no leaf of a GT tree; any other problem);
- `fact violated: placement`: an environment breaks a stated `on(x, y)` / `inside(x, y)` fact (a
  placement not read); `fact violated: other fact`: any other stated fact (a state, an attribute,
  a compound fact);
- `not realised`: an environment does not realise the trajectory it claims in the generator's own
  plan (its construction log, or `n_realised < n_claimed`);
- `no layout` / `construction`: an environment not built (no layout for the selected objects; any
  other generation failure);
- `correct BT fails`: a well-formed environment breaking no fact in which the correct BT fails;
- `missed paths`: LogCov < 1 with every environment valid (a factor or branch not read or not
  planned), split into `missed paths: a value never set` (some GT condition, a variable's value on
  a tree edge, is realised in no environment: a factor not read, or read but never varied) and
  `missed paths: values set, paths not combined` (every value is set somewhere: the planner's
  grouping or selection);
- `faulty BT not revealed only`: FauDR < 1 with LogCov and SceVR at 100;
- `none`: 100/100/100; `unclassified`: a loss neither the figures nor the records explain.

With `--why` it lists under each development row the task ids per class (never a held-out or fresh
row's). Last line: `reader_losses <class>=<tasks over all rows> ...`.

    python benchmarks/reader_generalisation.py --dev-only --losses --why

`--compare OLD.json` lists every development task whose LogCov, SceVR or FauDR moved against an
earlier `--json` file, a fall marked `FALL`, and exits 1 when any task fell.

Last line: `reader_generalisation built_in=<LogCov>/<SceVR>/<FauDR> reworded=... new=...
dev2_new=... dev4_reworded=... dev4_new=... dev3_reworded=... dev3_new=... dev5_reworded=...
dev5_new=... dev6_reworded=... dev6_new=... dev7_reworded=... dev7_new=... dev8_reworded=...
dev8_new=... dev9_reworded=... dev9_new=... dev10_reworded=... dev10_new=... dev11_reworded=...
dev11_new=... dev12_reworded=... dev12_new=... dev13_reworded=... dev13_new=... dev14_reworded=... dev14_new=...
dev15_reworded=... dev15_new=... dev16_reworded=... dev16_new=... dev17_reworded=... dev17_new=...
dev18_reworded=... dev18_new=... dev19_reworded=... dev19_new=... dev20_reworded=... dev20_new=... dev21_reworded=... dev21_new=... dev22_reworded=... dev22_new=... dev23_reworded=... dev23_new=... dev24_reworded=... dev24_new=... dev25_reworded=... dev25_new=... dev26_reworded=... dev26_new=... dev27_reworded=... dev27_new=... dev28_reworded=... dev28_new=... dev29_reworded=... dev29_new=... dev30_reworded=... dev30_new=... dev31_reworded=... dev31_new=... dev32_reworded=... dev32_new=... dev33_reworded=... dev33_new=... dev34_reworded=... dev34_new=... dev35_reworded=... dev35_new=... dev36_reworded=... dev36_new=... dev37_reworded=... dev37_new=... dev38_reworded=... dev38_new=... dev39_reworded=... dev39_new=... dev40_reworded=... dev40_new=... dev41_reworded=... dev41_new=... dev42_reworded=... dev42_new=... dev43_reworded=... dev43_new=... dev44_reworded=... dev44_new=... dev45_reworded=... dev45_new=... dev46_reworded=... dev46_new=... held_out_reworded=... held_out_new=... held_out2_reworded=... held_out2_new=...` (with `--dev-only`, the development
rows only).
"""

from __future__ import annotations

import argparse
import json
import re
import tempfile
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from logicenveval.benchmark import load_tasks, task_ids
from logicenveval.domain.catalog import load_catalog
from logicenveval.model.task import Task
from logicenveval.model.tree import atomic_conditions
from logicenveval.offline.placement import described_placements
from logicenveval.runner.config import RunConfig
from logicenveval.runner.run import run

ROOT = Path(__file__).resolve().parents[1]
DEV = ROOT / "tests" / "data" / "reader_dev"
DEV2 = ROOT / "tests" / "data" / "reader_dev2"
HOLDOUT = ROOT / "tests" / "data" / "reader_holdout"
DEV3 = ROOT / "tests" / "data" / "reader_dev3"
DEV4 = ROOT / "tests" / "data" / "reader_dev4"
DEV5 = ROOT / "tests" / "data" / "reader_dev5"
DEV6 = ROOT / "tests" / "data" / "reader_dev6"
DEV7 = ROOT / "tests" / "data" / "reader_dev7"
DEV8 = ROOT / "tests" / "data" / "reader_dev8"
DEV9 = ROOT / "tests" / "data" / "reader_dev9"
DEV10 = ROOT / "tests" / "data" / "reader_dev10"
DEV11 = ROOT / "tests" / "data" / "reader_dev11"
DEV12 = ROOT / "tests" / "data" / "reader_dev12"
DEV13 = ROOT / "tests" / "data" / "reader_dev13"
DEV14 = ROOT / "tests" / "data" / "reader_dev14"
DEV15 = ROOT / "tests" / "data" / "reader_dev15"
DEV16 = ROOT / "tests" / "data" / "reader_dev16"
DEV17 = ROOT / "tests" / "data" / "reader_dev17"
DEV18 = ROOT / "tests" / "data" / "reader_dev18"
DEV19 = ROOT / "tests" / "data" / "reader_dev19"
DEV20 = ROOT / "tests" / "data" / "reader_dev20"
DEV21 = ROOT / "tests" / "data" / "reader_dev21"
DEV22 = ROOT / "tests" / "data" / "reader_dev22"
DEV23 = ROOT / "tests" / "data" / "reader_dev23"
DEV24 = ROOT / "tests" / "data" / "reader_dev24"
DEV25 = ROOT / "tests" / "data" / "reader_dev25"
DEV26 = ROOT / "tests" / "data" / "reader_dev26"
DEV27 = ROOT / "tests" / "data" / "reader_dev27"
DEV28 = ROOT / "tests" / "data" / "reader_dev28"
DEV29 = ROOT / "tests" / "data" / "reader_dev29"
DEV30 = ROOT / "tests" / "data" / "reader_dev30"
DEV31 = ROOT / "tests" / "data" / "reader_dev31"
DEV32 = ROOT / "tests" / "data" / "reader_dev32"
DEV33 = ROOT / "tests" / "data" / "reader_dev33"
DEV34 = ROOT / "tests" / "data" / "reader_dev34"
DEV35 = ROOT / "tests" / "data" / "reader_dev35"
DEV36 = ROOT / "tests" / "data" / "reader_dev36"
DEV37 = ROOT / "tests" / "data" / "reader_dev37"
DEV38 = ROOT / "tests" / "data" / "reader_dev38"
DEV39 = ROOT / "tests" / "data" / "reader_dev39"
DEV40 = ROOT / "tests" / "data" / "reader_dev40"
DEV41 = ROOT / "tests" / "data" / "reader_dev41"
DEV42 = ROOT / "tests" / "data" / "reader_dev42"
DEV43 = ROOT / "tests" / "data" / "reader_dev43"
DEV44 = ROOT / "tests" / "data" / "reader_dev44"
DEV45 = ROOT / "tests" / "data" / "reader_dev45"
DEV46 = ROOT / "tests" / "data" / "reader_dev46"
DEV47 = ROOT / "tests" / "data" / "reader_dev47"
DEV48 = ROOT / "tests" / "data" / "reader_dev48"
DEV49 = ROOT / "tests" / "data" / "reader_dev49"
DEV50 = ROOT / "tests" / "data" / "reader_dev50"
DEV51 = ROOT / "tests" / "data" / "reader_dev51"
DEV52 = ROOT / "tests" / "data" / "reader_dev52"
DEV53 = ROOT / "tests" / "data" / "reader_dev53"
DEV54 = ROOT / "tests" / "data" / "reader_dev54"
DEV55 = ROOT / "tests" / "data" / "reader_dev55"
DEV56 = ROOT / "tests" / "data" / "reader_dev56"
DEV57 = ROOT / "tests" / "data" / "reader_dev57"
DEV58 = ROOT / "tests" / "data" / "reader_dev58"
HOLDOUT2 = ROOT / "tests" / "data" / "reader_holdout2"
#: (row name, tasks folder; None = the built-in tasks)
SETS: tuple[tuple[str, Path | None], ...] = (
    ("built-in", None), ("reworded", DEV / "tasks_reworded"), ("new", DEV / "tasks_new"),
    ("dev2 new", DEV2 / "tasks_new"),
    ("dev4 reworded", DEV4 / "tasks_reworded"), ("dev4 new", DEV4 / "tasks_new"),
    ("dev3 reworded", DEV3 / "tasks_reworded"), ("dev3 new", DEV3 / "tasks_new"),
    ("dev5 reworded", DEV5 / "tasks_reworded"), ("dev5 new", DEV5 / "tasks_new"),
    ("dev6 reworded", DEV6 / "tasks_reworded"), ("dev6 new", DEV6 / "tasks_new"),
    ("dev7 reworded", DEV7 / "tasks_reworded"), ("dev7 new", DEV7 / "tasks_new"),
    ("dev8 reworded", DEV8 / "tasks_reworded"), ("dev8 new", DEV8 / "tasks_new"),
    ("dev9 reworded", DEV9 / "tasks_reworded"), ("dev9 new", DEV9 / "tasks_new"),
    ("dev10 reworded", DEV10 / "tasks_reworded"), ("dev10 new", DEV10 / "tasks_new"),
    ("dev11 reworded", DEV11 / "tasks_reworded"), ("dev11 new", DEV11 / "tasks_new"),
    ("dev12 reworded", DEV12 / "tasks_reworded"), ("dev12 new", DEV12 / "tasks_new"),
    ("dev13 reworded", DEV13 / "tasks_reworded"), ("dev13 new", DEV13 / "tasks_new"),
    ("dev14 reworded", DEV14 / "tasks_reworded"), ("dev14 new", DEV14 / "tasks_new"),
    ("dev15 reworded", DEV15 / "tasks_reworded"), ("dev15 new", DEV15 / "tasks_new"),
    ("dev16 reworded", DEV16 / "tasks_reworded"), ("dev16 new", DEV16 / "tasks_new"),
    ("dev17 reworded", DEV17 / "tasks_reworded"), ("dev17 new", DEV17 / "tasks_new"),
    ("dev18 reworded", DEV18 / "tasks_reworded"), ("dev18 new", DEV18 / "tasks_new"),
    ("dev19 reworded", DEV19 / "tasks_reworded"), ("dev19 new", DEV19 / "tasks_new"),
    ("dev20 reworded", DEV20 / "tasks_reworded"), ("dev20 new", DEV20 / "tasks_new"),
    ("dev21 reworded", DEV21 / "tasks_reworded"), ("dev21 new", DEV21 / "tasks_new"),
    ("dev22 reworded", DEV22 / "tasks_reworded"), ("dev22 new", DEV22 / "tasks_new"),
    ("dev23 reworded", DEV23 / "tasks_reworded"), ("dev23 new", DEV23 / "tasks_new"),
    ("dev24 reworded", DEV24 / "tasks_reworded"), ("dev24 new", DEV24 / "tasks_new"),
    ("dev25 reworded", DEV25 / "tasks_reworded"), ("dev25 new", DEV25 / "tasks_new"),
    ("dev26 reworded", DEV26 / "tasks_reworded"), ("dev26 new", DEV26 / "tasks_new"),
    ("dev27 reworded", DEV27 / "tasks_reworded"), ("dev27 new", DEV27 / "tasks_new"),
    ("dev28 reworded", DEV28 / "tasks_reworded"), ("dev28 new", DEV28 / "tasks_new"),
    ("dev29 reworded", DEV29 / "tasks_reworded"), ("dev29 new", DEV29 / "tasks_new"),
    ("dev30 reworded", DEV30 / "tasks_reworded"), ("dev30 new", DEV30 / "tasks_new"),
    ("dev31 reworded", DEV31 / "tasks_reworded"), ("dev31 new", DEV31 / "tasks_new"),
    ("dev32 reworded", DEV32 / "tasks_reworded"), ("dev32 new", DEV32 / "tasks_new"),
    ("dev33 reworded", DEV33 / "tasks_reworded"), ("dev33 new", DEV33 / "tasks_new"),
    ("dev34 reworded", DEV34 / "tasks_reworded"), ("dev34 new", DEV34 / "tasks_new"),
    ("dev35 reworded", DEV35 / "tasks_reworded"), ("dev35 new", DEV35 / "tasks_new"),
    ("dev36 reworded", DEV36 / "tasks_reworded"), ("dev36 new", DEV36 / "tasks_new"),
    ("dev37 reworded", DEV37 / "tasks_reworded"), ("dev37 new", DEV37 / "tasks_new"),
    ("dev38 reworded", DEV38 / "tasks_reworded"), ("dev38 new", DEV38 / "tasks_new"),
    ("dev39 reworded", DEV39 / "tasks_reworded"), ("dev39 new", DEV39 / "tasks_new"),
    ("dev40 reworded", DEV40 / "tasks_reworded"), ("dev40 new", DEV40 / "tasks_new"),
    ("dev41 reworded", DEV41 / "tasks_reworded"), ("dev41 new", DEV41 / "tasks_new"),
    ("dev42 reworded", DEV42 / "tasks_reworded"), ("dev42 new", DEV42 / "tasks_new"),
    ("dev43 reworded", DEV43 / "tasks_reworded"), ("dev43 new", DEV43 / "tasks_new"),
    ("dev44 reworded", DEV44 / "tasks_reworded"), ("dev44 new", DEV44 / "tasks_new"),
    ("dev45 reworded", DEV45 / "tasks_reworded"), ("dev45 new", DEV45 / "tasks_new"),
    ("dev46 reworded", DEV46 / "tasks_reworded"), ("dev46 new", DEV46 / "tasks_new"),
    ("dev47 reworded", DEV47 / "tasks_reworded"), ("dev47 new", DEV47 / "tasks_new"),
    ("dev48 reworded", DEV48 / "tasks_reworded"), ("dev48 new", DEV48 / "tasks_new"),
    ("dev49 reworded", DEV49 / "tasks_reworded"), ("dev49 new", DEV49 / "tasks_new"),
    ("dev50 reworded", DEV50 / "tasks_reworded"), ("dev50 new", DEV50 / "tasks_new"),
    ("dev51 reworded", DEV51 / "tasks_reworded"), ("dev51 new", DEV51 / "tasks_new"),
    ("dev52 reworded", DEV52 / "tasks_reworded"), ("dev52 new", DEV52 / "tasks_new"),
    ("dev53 reworded", DEV53 / "tasks_reworded"), ("dev53 new", DEV53 / "tasks_new"),
    ("dev54 reworded", DEV54 / "tasks_reworded"), ("dev54 new", DEV54 / "tasks_new"),
    ("dev55 reworded", DEV55 / "tasks_reworded"), ("dev55 new", DEV55 / "tasks_new"),
    ("dev56 reworded", DEV56 / "tasks_reworded"), ("dev56 new", DEV56 / "tasks_new"),
    ("dev57 reworded", DEV57 / "tasks_reworded"), ("dev57 new", DEV57 / "tasks_new"),
    ("dev58 reworded", DEV58 / "tasks_reworded"), ("dev58 new", DEV58 / "tasks_new"),
    ("held-out reworded", HOLDOUT / "tasks_reworded"), ("held-out new", HOLDOUT / "tasks_new"),
    ("held-out2 reworded", HOLDOUT2 / "tasks_reworded"), ("held-out2 new", HOLDOUT2 / "tasks_new"),
)
#: the unseen sets' rows, which show only their aggregate: their per-task figures and `--why`
#: reasons would be a tuning signal for whoever changes the reader (they run `--dev-only`)
UNSEEN = frozenset({"held-out reworded", "held-out new", "held-out2 reworded", "held-out2 new"})
#: development sets nobody has tuned on yet: `--dev-only` leaves them out too (`--fresh` puts
#: them back), so that a tuner's runs never show them; move a set out of here when its round starts
FRESH: frozenset[str] = frozenset({"dev57 reworded", "dev57 new", "dev58 reworded", "dev58 new"})
GENERATOR = "logicenvgen"


def originals() -> list[str]:
    """Built-in task ids the reworded set rewords (its `rewordings.json`)."""
    entries = json.loads((DEV / "rewordings.json").read_text(encoding="utf-8"))["rewordings"]
    return sorted({e["original"] for e in entries})


def run_set(tasks_dir: Path | None, ids: list[str], seed: int, workers: int,
            output: Path, records: dict[str, list[Record]] | None = None
            ) -> tuple[dict[str, dict[str, Any]], dict[str, str]]:
    """Per-task metrics of offline LogicEnvGen on `ids` of `tasks_dir`, and per task the first
    reason an environment was lost (a failed generation, an ill-formed environment or a violated
    constraint), so the weak spots can be read without opening the run. With `records`, every
    task's failures, problems, violations and correct-BT verdicts are added to it (for `losses`)."""
    config = RunConfig(model="offline", generators=(GENERATOR,), tasks=tuple(ids),
                       tasks_dir=None if tasks_dir is None else str(tasks_dir), seed=seed,
                       workers=workers, output=str(output), no_cache=True, fresh=True)
    outcome = run(config, show_progress=False)
    per_task: dict[str, dict[str, Any]] = outcome.results["per_task"][GENERATOR]
    why: dict[str, str] = {}
    for failure in outcome.results["failures"].get(GENERATOR, []):
        why.setdefault(failure["task"], failure["message"])
        if records is not None:
            records.setdefault(failure["task"], []).append(
                ("failure", f"{failure.get('stage') or 'unit'}: {failure['message']}"))
    realised: dict[str, set[str]] = {}
    with (outcome.run_dir / "samples.jsonl").open(encoding="utf-8") as lines:
        for line in lines:
            sample = json.loads(line)
            lost = sample.get("problems") or sample.get("violations")
            if lost:
                why.setdefault(sample["task_id"], str(lost[0]))
            if records is not None:
                records.setdefault(sample["task_id"], []).extend(sample_records(sample))
                realised.setdefault(sample["task_id"], set()).update(
                    f"{var}={value}" for var, value in sample.get("conditions") or [])
    if records is not None:
        for task in load_tasks(tasks_dir, ids):
            records.setdefault(task.id, []).extend(unset_records(task, realised.get(task.id, set())))
    return per_task, why


def task_row(m: dict[str, Any]) -> tuple[float, float, float]:
    """(LogCov, SceVR, FauDR) of one task, as `metrics.compute` aggregates them."""
    slots = m["n_envs"] + m["n_failed"]
    faudr = m["faudr"]
    return (m["logcov"], m["n_valid"] / slots if slots else 0.0,
            sum(1.0 for v in faudr.values() if v) / len(faudr))


def aggregate(per_task: dict[str, dict[str, Any]]) -> tuple[float, float, float]:
    """LogCov and FauDR: mean over tasks; SceVR: valid environments over all attempted (as
    `metrics.compute.aggregate` does)."""
    rows = [task_row(m) for m in per_task.values()]
    slots = sum(m["n_envs"] + m["n_failed"] for m in per_task.values())
    valid = sum(m["n_valid"] for m in per_task.values())
    return (sum(r[0] for r in rows) / len(rows), valid / slots if slots else 0.0,
            sum(r[2] for r in rows) / len(rows))


#: a constraint fact that states one placement: `on(x, y)` or `inside(x, y)`, nothing else
_PLACEMENT = re.compile(r"^\s*(on|inside)\(\s*([a-z0-9_]+)\s*,\s*([a-z0-9_]+)\s*\)\s*$")


@dataclass(frozen=True)
class Recall:
    """How many of a set's stated placement facts the reader states, and the ones it missed as
    (task, fact, says)."""

    read: int
    stated: int
    missed: tuple[tuple[str, str, str], ...]

    @property
    def share(self) -> float:
        """Read over stated; 0.0 when the set states none (printed as `-`)."""
        return self.read / self.stated if self.stated else 0.0


def placement_recall(tasks_dir: Path | None, ids: list[str]) -> Recall:
    """The reader's recall of the placements the tasks `ids` of `tasks_dir` state: each
    constraint whose fact is one `on`/`inside` (`_PLACEMENT`) counts, read when
    `described_placements` of the task's own brief (its roles, so naming is out of the figure)
    states the same fact."""
    catalog = load_catalog()
    read, stated, missed = 0, 0, []
    for task in load_tasks(tasks_dir, ids):
        told = {re.sub(r"\s+", "", fact) for fact in described_placements(task.brief().model_dump(mode="json"), catalog)}
        for constraint in task.constraints:
            if not _PLACEMENT.match(constraint.fact):
                continue
            stated += 1
            if re.sub(r"\s+", "", constraint.fact) in told:
                read += 1
            else:
                missed.append((task.id, constraint.fact, constraint.says))
    return Recall(read, stated, tuple(missed))


def print_placements(sets: list[tuple[str, Path | None]], smoke: bool, why: bool) -> None:
    """Per row, the share of stated placements read; with `why` each missed one, for development
    rows only (a held-out or fresh row's facts would be a tuning signal)."""
    print("stated placements the offline reader states (task roles, `described_placements`):")
    print(f"  {'row':30s} {'read':>5s} {'stated':>6s} {'share':>6s}")
    figures = []
    for name, folder in sets:
        ids = task_ids(folder)
        recall = placement_recall(folder, ids[:2] if smoke else ids)
        share = pct(recall.share) if recall.stated else "-"  # no stated placement: nothing to read
        figures.append(f"{row_key(name)}={share.strip()}")
        print(f"  {name:30s} {recall.read:5d} {recall.stated:6d} {share:>6s}")
        if why and name not in UNSEEN | FRESH:
            for task_id, fact, says in recall.missed:
                print(f"      missed {task_id}: {fact}  says: {says!r}")
    print("placement_recall " + " ".join(figures))


#: one thing a run recorded about a task: (source, message), the source one of `failure` (a
#: generation failure, `stage: message`), `problem` (why an environment is ill-formed),
#: `violation` (a stated fact the environment breaks), `verdict` (the correct BT fails in it) or
#: `unset` (a GT condition no environment realises, `var=value`: only splits `missed paths`)
Record = tuple[str, str]

#: (source, pattern, loss class): a record counts in the class of the first entry whose source
#: is its own and whose pattern it matches; extend by adding rows (more specific ones first)
MESSAGE_CLASSES: tuple[tuple[str, re.Pattern[str], str], ...] = (
    ("problem", re.compile(r"^role \S+ is not bound"), "unbound role"),
    ("problem", re.compile(r"reaches no leaf"), "ill-formed: no leaf"),
    ("problem", re.compile(r""), "ill-formed: other"),
    ("violation", re.compile(r"constraint (?:on|inside)\(\s*\w+\s*,\s*\w+\s*\) \(the description"),
     "fact violated: placement"),
    ("violation", re.compile(r""), "fact violated: other fact"),
    ("failure", re.compile(r"does not realise its trajectory"), "not realised"),
    ("failure", re.compile(r"no layout"), "no layout"),
    ("failure", re.compile(r""), "construction"),
    ("verdict", re.compile(r""), "correct BT fails"),
)


def _faudr(m: dict[str, Any]) -> float:
    return task_row(m)[2]


#: (loss class, test on the task's metrics `task_row` and `TaskMetrics` fields): the classes the
#: figures alone show
METRIC_CLASSES: tuple[tuple[str, Callable[[dict[str, Any]], bool]], ...] = (
    ("missed paths", lambda m: m["logcov"] < 1 and m["n_failed"] == 0 and m["n_valid"] == m["n_envs"]),
    ("not realised", lambda m: m.get("n_realised", 0) < m.get("n_claimed", 0)),
    ("faulty BT not revealed only", lambda m: _faudr(m) < 1 and task_row(m)[:2] == (1.0, 1.0)),
    ("none", lambda m: task_row(m) == (1.0, 1.0, 1.0)),
)
#: how `missed paths` splits, by whether some GT condition (a variable's value on a tree edge,
#: C_total) is realised in no environment (`unset` records): a factor not read, or read but never
#: varied, versus every value set somewhere but the paths not combined (the planner's grouping)
MISSED_SPLIT = ("missed paths: a value never set", "missed paths: values set, paths not combined")
#: every class, in the order `--losses` prints them; `unclassified`: a loss no row names
LOSS_CLASSES: tuple[str, ...] = tuple(dict.fromkeys(
    [c for _, _, c in MESSAGE_CLASSES] + [c for c, _ in METRIC_CLASSES] + list(MISSED_SPLIT)
    + ["unclassified"]))


def unset_records(task: Task, realised: set[str]) -> list[Record]:
    """One `unset` record per GT condition (C_total, `var=value`) no environment of the task
    realises, given the `realised` ones (the samples' `conditions`)."""
    return [("unset", f"{var}={value}") for var, value in atomic_conditions(task)
            if f"{var}={value}" not in realised]


def sample_records(sample: dict[str, Any]) -> list[Record]:
    """The records of one environment of `samples.jsonl`: its problems, its violations, and, when
    it is well-formed and breaks no fact, a correct BT that does not pass."""
    out: list[Record] = [("problem", str(p)) for p in sample.get("problems") or []]
    out += [("violation", str(v)) for v in sample.get("violations") or []]
    verdict = (sample.get("verdicts") or {}).get("correct")
    if sample.get("well_formed") and not sample.get("violations") and verdict != "passed":
        out.append(("verdict", f"correct BT: {verdict}"))
    return out


def record_class(record: Record) -> str:
    """The loss class of one record (`MESSAGE_CLASSES`), `unclassified` when no row matches."""
    source, message = record
    return next((c for s, pattern, c in MESSAGE_CLASSES if s == source and pattern.search(message)),
                "unclassified")


def loss_classes(m: dict[str, Any], records: list[Record]) -> set[str]:
    """Every class a task loses in (several at once), from its metrics `m` and its `records`;
    `unclassified` when it is not 100/100/100 and neither its figures nor its records say why."""
    classes = {record_class(r) for r in records if r[0] != "unset"}
    classes |= {c for c, test in METRIC_CLASSES if test(m)}
    if "missed paths" in classes:
        classes.add(MISSED_SPLIT[0] if any(r[0] == "unset" for r in records) else MISSED_SPLIT[1])
    if not classes:
        classes.add("unclassified")
    return classes


def losses(results: dict[str, dict[str, dict[str, Any]]], records: dict[str, dict[str, list[Record]]]
           ) -> dict[str, dict[str, list[str]]]:
    """Per row, per loss class, the ids of the tasks counting in it."""
    out: dict[str, dict[str, list[str]]] = {}
    for name, per in results.items():
        classes: dict[str, list[str]] = {c: [] for c in LOSS_CLASSES}
        for task_id, m in per.items():
            for c in sorted(loss_classes(m, records.get(name, {}).get(task_id, []))):
                classes[c].append(task_id)
        out[name] = classes
    return out


#: what the last line's class keys replace by `_` (spaces, colons, commas)
_WORDLESS = re.compile(r"\W+")


def print_losses(table: dict[str, dict[str, list[str]]], why: bool) -> None:
    """Per row, how many tasks count in each loss class (counts only); with `why`, the task ids
    per class of a development row (a held-out or fresh row's ids would be a tuning signal)."""
    print("where tasks lose (offline LogicEnvGen; task counts per class, a task may count in several):")
    for name, classes in table.items():
        n = len({t for ids in classes.values() for t in ids})
        counts = ", ".join(f"{c} {len(ids)}" for c, ids in classes.items() if ids)
        print(f"  {name:20s} {n:3d} tasks: {counts}")
        if why and name not in UNSEEN | FRESH:
            for c, ids in classes.items():
                if ids and c != "none":
                    print(f"      {c}: {' '.join(ids)}")
    totals = {c: sum(len(classes[c]) for classes in table.values()) for c in LOSS_CLASSES}
    print("reader_losses " + " ".join(f"{_WORDLESS.sub('_', c)}={n}" for c, n in totals.items()))


def row_key(name: str) -> str:
    """A row's key on a last line (`reader_generalisation`, `placement_recall`): "dev17 new" is
    `dev17_new`, "held-out reworded" `held_out_reworded`."""
    return name.replace("-", "_").replace(" ", "_")


def pct(x: float) -> str:
    return f"{100 * x:5.1f}"


def compare(old: dict[str, Any], new: dict[str, Any]) -> tuple[list[str], int]:
    """The lines of every task in both `--json` files whose figures moved, and how many fell. A
    task of a set the old file lacks is new, not moved."""
    lines, fell = [], 0
    for row, tasks in new["per_task"].items():
        for task_id, m in tasks.items():
            before = old["per_task"].get(row, {}).get(task_id)
            if before is None:
                continue
            moved = {k: (before[k], v) for k, v in m.items() if abs(v - before[k]) > 1e-9}
            if not moved:
                continue
            down = any(v < b for b, v in moved.values())
            fell += down
            lines.append(f"  {'FALL' if down else 'gain'} {row:13s} {task_id:32s} " + " ".join(
                f"{k} {pct(b).strip()} -> {pct(v).strip()}" for k, (b, v) in moved.items()))
    return lines, fell


def skipped_rows(skip: str, only: str) -> set[str]:
    """The rows `--skip` and `--only` leave out: the rows named by `skip`, and with `only` every
    row it does not name. A name no row has is a ValueError (a misspelt fresh set must not run)."""
    names = {name for name, _ in SETS}
    skipped = {s.strip() for s in skip.split(",") if s.strip()}
    kept = {s.strip() for s in only.split(",") if s.strip()}
    for option, said in (("--skip", skipped), ("--only", kept)):
        if said - names:
            raise ValueError(f"{option}: no set named {', '.join(sorted(said - names))}")
    return skipped | (names - kept if kept else set())


def selected(dev_only: bool, fresh: bool, skipped: set[str]) -> list[tuple[str, Path | None]]:
    """The sets a run measures: all, or with `dev_only` neither the held-out nor (unless `fresh`)
    the fresh ones; never the `skipped` ones."""
    return [(name, folder) for name, folder in SETS
            if not (dev_only and (name in UNSEEN or name in FRESH and not fresh)) and name not in skipped]


def print_tasks(results: dict[str, dict[str, dict[str, Any]]], why: dict[str, dict[str, str]],
                show_why: bool) -> None:
    """Each task's figures (not a held-out row's), with `show_why` its first loss (not a fresh
    row's: the reason would be a tuning signal, as a held-out row's would; measuring a fresh row
    with `--fresh --why` shows its figures only)."""
    print("per task (offline LogicEnvGen, --brief description):")
    print(f"  {'set':13s} {'task':32s} {'LogCov':>6s} {'SceVR':>6s} {'FauDR':>6s}")
    for name, per in results.items():
        if name in UNSEEN:
            continue
        for task_id, m in per.items():
            lc, sv, fd = task_row(m)
            print(f"  {name:13s} {task_id:32s} {pct(lc):>6s} {pct(sv):>6s} {pct(fd):>6s}")
            if show_why and name not in FRESH and task_id in why[name]:
                print(f"      first loss: {why[name][task_id][:200]}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--smoke", action="store_true", help="two tasks per set, for a quick check")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--workers", type=int, default=1)
    ap.add_argument("--work", default=None, help="run folders go here (default: a temporary folder)")
    ap.add_argument("--why", action="store_true", help="under each task, the first reason an environment was lost")
    ap.add_argument("--json", default=None, help="also write every figure to this JSON file")
    ap.add_argument("--compare", default=None, metavar="OLD.json",
                    help="list the development tasks whose figures moved against an earlier --json file; exit 1 if any fell")
    ap.add_argument("--dev-only", action="store_true",
                    help="skip the held-out sets and the fresh ones (whoever tunes the reader must not run it on them)")
    ap.add_argument("--fresh", action="store_true",
                    help="with --dev-only, keep the fresh development sets (FRESH): for measuring them, not for tuning")
    ap.add_argument("--skip", default="", metavar="SET[,SET]",
                    help="also skip these rows' sets, e.g. 'dev10 reworded,dev10 new': a fresh set "
                         "kept unseen while others tune the reader")
    ap.add_argument("--only", default="", metavar="SET[,SET]",
                    help="measure only these rows' sets, e.g. 'held-out reworded,held-out2 reworded' to bisect "
                         "a move of an unseen row on its aggregate at each commit (every tree has those rows, "
                         "so no skip list per tree); --dev-only still leaves the held-out and fresh rows out")
    ap.add_argument("--placements", action="store_true",
                    help="print instead each row's recall of stated placements (no generator is run); "
                         "with --why, each missed one (development rows only)")
    ap.add_argument("--losses", action="store_true",
                    help="instead of the per-task lines, per row how many tasks lose in each loss class "
                         "(counts only); with --why, the task ids per class (development rows only)")
    args = ap.parse_args()
    try:
        skipped = skipped_rows(args.skip, args.only)
    except ValueError as exc:
        ap.error(str(exc))
    sets = selected(args.dev_only, args.fresh, skipped)
    if args.placements:
        print_placements(sets, args.smoke, args.why)
        return
    work = Path(args.work) if args.work else Path(tempfile.mkdtemp(prefix="reader_generalisation-"))
    start = time.perf_counter()
    results: dict[str, dict[str, dict[str, Any]]] = {}
    why: dict[str, dict[str, str]] = {}
    records: dict[str, dict[str, list[Record]]] = {}
    for name, folder in sets:
        ids = task_ids(folder)
        if args.smoke:
            ids = ids[:2]
        records[name] = {}
        results[name], why[name] = run_set(folder, ids, args.seed, args.workers, work / name.replace(" ", "_"),
                                           records[name] if args.losses else None)
    rows = {name: aggregate(per) for name, per in results.items() if name not in UNSEEN}
    base = {k: v for k, v in results.get("built-in", {}).items() if k in originals()}
    if base:
        rows["built-in (reworded originals)"] = aggregate(base)
    rows.update({name: aggregate(per) for name, per in results.items() if name in UNSEEN})

    if args.losses:
        print_losses(losses(results, records), args.why)
    else:
        print_tasks(results, why, args.why)
    print()
    print(f"  {'row':30s} {'tasks':>5s} {'LogCov':>6s} {'SceVR':>6s} {'FauDR':>6s}")
    for name, (lc, sv, fd) in rows.items():
        n = len(base) if name.startswith("built-in (") else len(results[name])
        print(f"  {name:30s} {n:5d} {pct(lc):>6s} {pct(sv):>6s} {pct(fd):>6s}")
    print(f"seconds={time.perf_counter() - start:.0f} runs={work}")
    per_task = {s: {t: dict(zip(("logcov", "scevr", "faudr"), task_row(m), strict=True))
                    for t, m in per.items()} for s, per in results.items() if s not in UNSEEN}
    if args.json:
        Path(args.json).write_text(json.dumps({
            "rows": {k: {"logcov": v[0], "scevr": v[1], "faudr": v[2]} for k, v in rows.items()},
            "per_task": per_task,
        }, indent=1) + "\n", encoding="utf-8")
    print("reader_generalisation " + " ".join(
        f"{row_key(name)}={'/'.join(pct(x).strip() for x in rows[name])}"
        for name, _ in sets))
    if args.compare:
        lines, fell = compare(json.loads(Path(args.compare).read_text(encoding="utf-8")), {"per_task": per_task})
        print(f"against {args.compare}:")
        print("\n".join(lines) or "  no development task moved")
        print(f"tasks that fell: {fell}")
        if fell:
            raise SystemExit(1)


if __name__ == "__main__":
    main()
