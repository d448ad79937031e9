"""The reader's fifth to fifty-eighth development sets (tests/data/reader_dev5/, reader_dev6/,
reader_dev7/, reader_dev8/, reader_dev9/, reader_dev10/, reader_dev11/, reader_dev12/, reader_dev13/,
reader_dev14/, reader_dev15/, reader_dev16/, reader_dev17/, reader_dev18/, reader_dev19/, reader_dev20/,
reader_dev21/, reader_dev22/, reader_dev23/, reader_dev24/, reader_dev25/, reader_dev26/,
reader_dev27/, reader_dev28/, reader_dev29/, reader_dev30/, reader_dev31/, reader_dev32/, reader_dev33/, reader_dev34/, reader_dev35/, reader_dev36/, reader_dev37/, reader_dev38/, reader_dev39/, reader_dev40/, reader_dev41/, reader_dev42/, reader_dev43/, reader_dev44/, reader_dev45/, reader_dev46/, reader_dev47/, reader_dev48/, reader_dev49/, reader_dev50/, reader_dev51/, reader_dev52/, reader_dev53/, reader_dev54/, reader_dev55/, reader_dev56/, reader_dev57/, reader_dev58/): new tasks and rewordings written from the task format, the
catalog and the built-in tasks, without reading the offline reader or running it on them, for rounds of reader
rules to be tuned on. One table of what differs between them; the same checks for each.

The honesty checks every set has (`reader_sets`): rewordings that change only the wording and
still name every object, BTs byte-identical to their originals, every object named, a current
mutant list, and every task valid (one of each kind in the default run, all in the slow run).
What these sets promise beyond the earlier ones: each new task is in a register and a room id no
earlier development set uses, with at least one object kind no built-in task uses (the catalog's
pool of kinds no set uses being nearly exhausted); the rewordings' registers repeat no earlier
set's. dev 5's rewordings cover the 13 built-in tasks the first development set leaves out, so
development covers every built-in task; dev 6 to dev 14 put their weight on new tasks, since
the held-out sets' new tasks lagged while every development row had reached 100. dev 12 and
dev 13 were written side by side: dev 12 in registers of speech and personal writing and room ids
beginning with a letter a-l, dev 13 in registers of documents, forms and genre writing and room
ids beginning with a letter m-z. dev 14 came after both, in registers of neither family
(performance, instructions for machines and games, quizzes, signage, lists of other kinds,
non-native English of speakers of languages no set used). dev 15 came after dev 14, in families
barely touched before: workplace and trade writing (a plumber's job ticket, a police briefing),
messaging formats with their own structure (an email reply chain, a forum post quoting earlier
posts), writing of another period (a Victorian household manual, a 1950s advertisement), a child's
dictation written down by an adult and a careless machine translation. dev 16 came after dev 15,
in registers no set used: documents of a tenancy (a check-in inventory, a landlord's letter in a
deposit dispute), school and home life (a teacher's instructions to pupils, a dream journal), a
voice other than the writer's (a letter from the family cat) and the English of Brazilian
Portuguese and Dutch speakers. dev 17 came after dev 16, beside dev 18: registers of spoken,
broadcast, official and commercial writing (courtroom testimony, an insurance claim form, a
building manager's notice, a support chatbot log, a product-recall notice, a TV shopping-channel
segment, Hansard, a radio news bulletin) and a Spanish speaker's English, in room ids beginning
with a-m (dev 18's begin with n-z). dev 18 was written beside dev 17 (each in its own family
of registers): personal, literary and digital writing (a letter to one's future self, a Regency-novel
and a Gothic-tale pastiche, a captain's log in the manner of science fiction, a Homeric epic, an
Instagram caption, a speech-to-text dictation, a sonnet) and the English of a Korean speaker, in
room ids beginning with a letter n-z. dev 19 was written in the eleventh session, beside dev 20:
registers of work, service and the trades and of science and technology (a vet nurse's SBAR
handover, a builder's snagging list, an on-call runbook, a mathematician's claim and proof, an
ecologist's field record sheet, a chemical safety data sheet, a call-centre script, a paper's
Materials and Methods section) and the English of a Mandarin Chinese speaker, in room ids
beginning with a letter a-m.
dev 20 was written in the eleventh session beside dev 19 (each
in its own family of registers): family, community, leisure and entertainment writing (a Scout
badge card, a podcast's opening housekeeping, a fan-fiction chapter with author's notes, a bingo
caller's patter, a best man's speech, a film-trailer voice-over, a square-dance caller's calls, a
Christmas round-robin letter) and the English of a Greek speaker, in room ids beginning with a
letter n-z.
dev 21 was written in the twelfth session beside dev 22 (each in its own family of registers):
sport, travel, health and education writing (a swimming coach's session sheet, a golf club's
scorecard with local rules, a walking guidebook's bothy entry, a tour operator's itinerary, a
physiotherapist's home exercise programme, a medicine's patient information leaflet, a language
lab induction worksheet for Year 7, a primary school's end-of-term report card) and the English of
a Polish speaker, in room ids beginning with a letter a-m.
dev 22 was written in the twelfth session beside dev 21 (each in its own family of registers):
writing of law, religion, history, the arts and the old-fashioned (a mock last will and
testament, a monastic rule, a wartime public information leaflet, an artist's instruction pieces,
an old-fashioned reading primer, an Act of Parliament, a medieval chronicle's annal, an opera
libretto) and the English of a Polish speaker, in room ids beginning with a letter n-z.
dev 23 was written in the thirteenth session beside dev 24 (each in its own family of registers):
writing of food and drink, farming and gardening, animals, nature and the weather (a beekeeper's
hive inspection record, a seed packet, a wine merchant's tasting note, a dog walker's handover
text, a shipping forecast, a farmer's almanac page, a restaurant critic's review, a bird field
guide's species account) and the English of a Swahili speaker, in room ids beginning with a
letter a-m.
dev 24 was written in the thirteenth session beside dev 23 (each in its own family of registers):
writing of commerce, the media, the internet and officialdom (an online marketplace listing, a
customer's product review, a newspaper's corrections and clarifications column, a planning
decision notice, a to-do app's automated e-mail digest, a cleaning firm's quotation, a
government guidance web page, a TV listings page) and the English of a Swedish speaker, in room
ids beginning with a letter n-z.
dev 25 was written in the fourteenth session beside dev 26 (each in its own family of registers):
writing of sport, games and hobbies, travel and transport (a karate club's dojo etiquette sheet,
a railway engineering-works notice, a cycling club's ride sheet, a chess arbiter's announcement,
an airline boarding pass, a driving examiner's instructions, a darts MC's calling, a climbing
wall's safety briefing) and the English of a Vietnamese speaker, in room ids beginning with a
letter a-m.
dev 26 was written in the fourteenth session beside dev 25 (each in its own family of registers):
writing of science, medicine, engineering and the trades (a GP's referral letter, an electrical
installation condition report's observations, a service manual's troubleshooting table, a peer
reviewer's report, an engineering maintenance task card, a surgical safety checklist, a garage's
vehicle health check, a clinical trial protocol synopsis) and the English of a Finnish speaker, in
room ids beginning with a letter n-z.
dev 27 was written in the fifteenth session beside dev 28 (each in its own family of registers):
writing of law, finance, insurance, government forms and religious life (a solicitor's letter
before action, a building society's account statement, an insurance product information
document, an application form with its guidance notes, a chapel's order of service, a family
court's consent order, a company's notice of annual general meeting, a catechism) and the English
of a Turkish speaker, in room ids beginning with a letter a-m.
dev 28 was written in the fifteenth session beside dev 27 (each in its own family of registers):
writing of childcare, elder care, hospitality, retail and farming (a day nursery's daily diary, a
home care agency's daily visit record, a pub's taproom close-down card, a store chain's weekly
store communication, a dairy farm's relief milker notes, a telecare operator's call-out sheet, a
garden centre's aftercare job card, a farm volunteer's morning card) and the English of a
Hungarian speaker, in room ids beginning with a letter n-z.
dev 29 was written in the fifteenth session beside dev 30 (each in its own family of registers):
writing of the arts, music, theatre, crafts and museums (a stage manager's rehearsal report, a
band's set list, a life-drawing class's session plan, a historic house museum's housekeeping
schedule, a pottery studio's members' notice, a radio play's script, a quilting pattern, a concert
programme note) and the English of an Arabic speaker, in room ids beginning with a letter a-m.
dev 30 was written in the fifteenth session beside dev 29 (each in its own family of registers):
registers of emergency services, the armed forces, aviation, shipping and security (a fire
station's watch handover log, a battalion's Part One Orders, a flying club's crew-room NOTAM, a
ship master's night order book, a guarding company's assignment instructions, a cargo
superintendent's stowage instruction, a QRH non-normal checklist, a control room's protocol card)
and the English of a Romanian speaker, in room ids beginning with a letter n-z.
dev 32 was written in the sixteenth session beside dev 31 (each in its own family of registers,
neither opened by the other): registers of utilities and energy, broadcasting and telecoms, zoos
and wildlife parks, surveying and mapping, and beekeeping and brewing (an electricity network's
planned power-cut notice, a broadband engineer's appointment confirmation, a zoo keeper's daily
round sheet, a land surveyor's field notes, a home brewer's batch log, a beekeeping association's
jobs-for-the-month column, a live television running order, a water company's notice to a
customer) and the English of an Indonesian speaker, in room ids beginning with a letter n-z.
dev 33 was written in the seventeenth session beside dev 34 (each in its own family of registers,
neither opened by the other): registers of politics and elections, journalism and magazines,
fashion and textiles, astronomy and space flight, and software operations (a candidate's election
leaflet, an interiors magazine's room-of-the-month feature, a fashion tech pack, a space station's
onboard short-term plan, a pull request's code review, an incident postmortem, a news website's
live blog, an amateur astronomer's observing plan) and the English of a Ukrainian speaker, in room
ids beginning with a letter a-m.
dev 34 was written in the seventeenth session beside dev 33 (each in its own family of registers,
neither opened by the other): registers of mining and quarrying, forestry and fisheries, libraries
and archives, advertising and marketing, and film and television production (a pit deputy's
statutory inspection report, a fishing skipper's standing orders, an archive's catalogue entry, an
advertising agency's creative brief, a location call sheet, a costume department's wardrobe and
laundry notes, a tree nursery's daily operations worksheet, a library's shelving guide for
volunteers) and the English of a Thai speaker, in room ids beginning with a letter n-z.
dev 35 was written in the eighteenth session beside dev 36 (each in its own family of registers,
neither opened by the other): registers of cartography and orienteering, perfumery and cosmetics,
wilderness guiding and camping, crossword setting and word games, and auditing and tax compliance
(a surveyor's map sheet with its legend, a perfumer's formula card, a mountain leader's camp
briefing, a prize cryptic crossword with its solutions, an internal audit report, an orienteering
course's notes, a cosmetics carton's directions for use, a tax authority's compliance check letter)
and the English of a Czech speaker, in room ids beginning with a letter a-m.
dev 36 was written in the eighteenth session beside dev 35 (each in its own family of registers,
neither opened by the other): registers of tram and bus transit operations, ballet and dance,
postal and parcel services, circus and stage magic, and locksmithing and home security (a tram
depot's notice to drivers, a ballet mistress's rehearsal notes, a sub-postmaster's instructions to
a relief, a stage magician's routine sheet, a locksmith's home security survey, a line-dance step
sheet, a circus ring crew's cue sheet, a bus driver's duty card) and the
English of a Bengali speaker, in room ids beginning with a letter n-z.
dev 37 was written in the nineteenth session beside dev 38 (each in its own family of registers,
neither opened by the other): registers of glassblowing and glass studios, falconry and bird
handling, archaeological excavation, weather stations and meteorology, and cricket scoring and
umpiring (a glass studio's hot-shop shutdown card, a falconer's mews notes, an excavation's
context sheet, a climatological station's observer's daily register, a cricket scorer's
close-of-play notes, the Laws of Cricket as a household code, an archaeological Written Scheme of
Investigation, a glassblowing gaffer's piece plan) and the English of a Yoruba speaker, in room ids
beginning with a letter a-m.
dev 38 was written in the nineteenth session beside dev 37 (each in its own family of registers,
neither opened by the other): registers of watch and clock repair, scuba diving and dive centres,
air traffic control, bookbinding and letterpress printing, and tailoring and dressmaking (a
watchmaker's repair job ticket, a dive centre's closing checklist, a tower controller's position
relief briefing, a letterpress job docket, a tailor's alteration ticket, a dive guide's site
briefing, a mechanical watch's instructions for use, an aerodrome's ATIS broadcast) and the
English of a Hebrew speaker, in room ids beginning with a letter n-z.
dev 39 was written in the twenty-first session beside dev 40 (each in its own family of registers,
neither opened by the other): registers of veterinary practice, church bell-ringing, chess
arbitration, pharmacy and livery yards (a vet nurse's dog-ward close-down sheet, a tower captain's
practice notes, a chess arbiter's venue checklist, a pharmacist's locum handover, a livery yard's
holiday cover sheet, a change-ringing method sheet, a pharmacy dispensing label, a dressage test
sheet) and the English of a Malay speaker, in room ids beginning with a letter a-m.
dev 40 was written in the twenty-first session beside dev 39 (each in its own family of registers,
neither opened by the other): registers of railway signalling, barbering, rowing, wine service and
motor racing (a signaller's turn handover, a barber shop's closing routine, a rowing club boatman's
notes, a cellar master's list, a pit garage's close-down sheet, a hair salon's junior training
card, a module of a railway rule book, a pit-stop procedure) and the English of a Tamil speaker,
in room ids beginning with a letter n-z.
dev 41 was written after dev 40 (without opening dev 39): registers of outdoor and animal work (a lido
lifeguard room's close-down sheet, a ski patrol hut's closing notes, a boarding cattery's weekend
cover notes, a shepherd's notes for the night lamber, a canal's volunteer lock keepers' end-of-shift
notice, a pheasant shoot headkeeper's word to the beaters, a countryside ranger service's volunteer
task sheet, a wildlife rescue's foster care sheet) and the English of a Vietnamese speaker (a
neighbour's note), in room ids beginning with a letter a-m.
dev 42 was written after dev 40's tenth measurement (no other set opened but through its README,
its rewordings' registers and its room ids): registers of technical and institutional work (a
data-centre operations shift log, a university cleanroom's gowning notice, a hospital porters'
note for nights, a Crown Court usher's notes for a relief usher, a register office's ceremony
room clear-down sheet, a permit to work, a records retention and disposal schedule, a standard
operating procedure) and the English of a Turkish speaker (a landlady's note to her tenant), in
room ids beginning with a letter n-z.
dev 43 was written after dev 42 (earlier sets read only through their READMEs, their rewordings'
registers and their room ids, but for one dev 40 task taken whole as a template and the format of
dev 40's rewordings.json; dev 41, dev 42 and dev 44 not opened at all): registers of care and
service work done in other people's places (a district nurse's continuation notes, a funeral
director's chapel of rest viewing checklist, a removal firm's pack and load sheet, a hotel's
in-room dining collection card, a night nanny's log, a disabled employer's guide for her personal
assistants, an au pair handbook's page, a home-from-hospital volunteer's task card) and the
English of a Nepali speaker (a live-in carer's note), in room ids beginning with a letter a-m.
dev 44 was written after dev 42 (beside dev 43, which it never opened; dev 41 and dev 42 known only
through this docstring): registers of making and repairing things (a bicycle workshop's job card, a
piano tuner's visit notes, a boatyard's winter lay-up list, a blacksmith's end-of-day card, a repair
café's closing sheet, a screen-print shop's end-of-run checklist, a dolls' hospital's discharge and
aftercare note, flat-pack furniture assembly instructions) and the English of a Nepali speaker (a
flatmate's note), in room ids beginning with a letter n-z.
dev 45 was written after dev 44 (beside dev 46, which it never opened; dev 43 known only through
this docstring): registers of transport and travel work (a Gozo ferry bosun's note for the crew
mess, a bus garage controller's handover log, a railway station's closing-down book, a marina
berthing master's cover e-mail, a removal crew's group chat, a coach tour manager's departure
letter, a sleeper train host's cabin preparation card, a removal firm's evening-before e-mail, a
coach driver's walkaround check sheet as a bedtime house check) and the English of a Maltese
speaker (the ferry bosun's note), in room ids beginning with a letter a-m.
dev 46 was written after dev 44 (beside dev 45, which it never opened; dev 43 and dev 44 known only
through this docstring and dev 44's README): registers of education and children (a day nursery's
toddler room closing handover, a school site manager's lettings note for a relief caretaker, a Scout
group quartermaster's camp returns note, a children's library's Saturday closing procedure, a
swimming club's gala team room pack-down, a Year 1 home challenge card, a boarding house matron's
laundry room notice, Montessori practical-life work cards) and the English of a Georgian speaker (a
music school piano teacher's note), in room ids beginning with a letter n-z.
dev 47 was written after dev 46 (beside dev 48, which it never opened; dev 43 known only through
this docstring): registers of emergency services, security and public safety work (a lifeboat
station helm's crew-room notes after a shout, a condominium security officer's note to his night
relief, a mountain rescue team's kit room after-call-out card, a coastwatch station's log with
notes for the next watch, a police front counter's close-down notes, an ambulance station's day
room book-off card, a fire incident commander's radio tasking, a security company's keyholding
site instructions, a search and rescue team's task assignment sheet) and the English of a Haitian
Creole speaker (the security officer's note), in room ids beginning with a letter a-m.
dev 48 was written after dev 46 (beside dev 47, which it never opened; dev 43 known only through
this docstring): registers of retail, markets and shop work (a charity shop manager's sorting room
day book, a florist's order book with her closing notes, a second-hand bookseller's letter to the
friend minding her shop, a hardware shop owner's closing note, a market trader's texts to his
daughter locking up the lock-up, a bridal boutique's stylist handbook section, a furniture store's
room-set display standards card, a supermarket's tannoy announcement to colleagues, a shop's returns
and exchanges policy notice) and the English of a Bosnian speaker (the hardware shop owner's note),
in room ids beginning with a letter n-z.
dev 49 was written after dev 48 (beside dev 50, which it never opened; dev 43 known only through
this docstring): registers of food and drink production work (a microbrewery head brewer's
late-shift handover, a Basque cider maker's note to his helper, a coffee roastery's end-of-day close
list, a smokehouse's day book with notes for the owner's son, a gin distillery manager's Friday close
e-mail, a farmhouse cheesemaker's make sheet, a vineyard winery's vintage cellar work order, a chilled
desserts factory's hygiene lobby procedure, a confectionery factory's line clearance checklist) and
the English of a Basque speaker (the cider maker's note), in room ids beginning with a letter a-m.
dev 50 was written after dev 48 (beside dev 49, which it never opened; dev 43 known only through
this docstring): registers of religious, funeral and community caretaking work (a church verger's
notes for the relief verger, a mosque caretaker's note for the wudu area, a synagogue caretaker's
Friday note for the cleaner, a crematorium's chapel attendants' between-services card, a Quaker
meeting house warden's notes for the lock-up rota, a gurdwara langar kitchen note, a church good
neighbours scheme's visit card, a Salvation Army lifehouse's room changeover sheet, an almshouse
warden's weekly check sheet) and the English of a Punjabi speaker (the langar kitchen note), in room ids
beginning with a letter n-z.
dev 51 was written after dev 50 (beside dev 52, which it never opened; dev 43 known only through
this docstring): registers of sports ground, stable and leisure facility work (an ice rink duty
manager's skate hire close-down notes, a bowls club's pavilion tea rota lock-up card, a leisure
centre pool plant operator's log with notes for the relief, a racecourse head valet's notes for the
jockeys' room, a dry ski slope head of snowsports' WhatsApp hut list, an Icelandic horse stud's
foaling unit night-watch note, a football ground safety officer's post-match sweep briefing, a
parkrun run director's pre-run briefing, a racing yard's evening stables round card) and the English
of an Icelandic speaker (the stud owner's note), in room ids beginning with a letter a-m.
dev 52 was written after dev 50 (beside dev 51, which it never opened; dev 43 known only through
this docstring): registers of laboratory and collections work (a herbarium curator's note for the
mounting volunteer, a public aquarium's back-of-house aquarist handover, a seed bank technician's
note to the student helper, a university teaching lab's end-of-practical checklist for
demonstrators, a natural history museum spirit collection manager's e-mail, a geology rock
preparation room technician's notes, a museum's integrated pest management inspection record, a
university animal facility's daily husbandry check sheet, a museum registrar's object location
audit) and the English of a Lithuanian speaker (the seed bank technician's note), in room ids
beginning with a letter n-z.
dev 53 was written after dev 52 (beside dev 54, which it never opened; dev 43 known only through
this docstring): registers of utilities and infrastructure work (a water treatment works' day-to-night
shift handover for the dosing room, a primary substation's site log with the Senior Authorised
Person's notes for the battery room, a wastewater team leader's e-mail before a sewage pumping
station visit, a telephone exchange senior technician's night-duty note, a reservoir keeper's weekend
cover notes for the gauge house, a tidal flood barrier's control shift log, an electricity control
engineer's switching programme, a wind turbine technician's service checklist, a gas emergency
service call handler's script) and the English of a Telugu speaker (the telephone exchange note), in
room ids beginning with a letter a-m.
dev 54 was written after dev 52 (beside dev 53, which it never opened; dev 43 known only through
this docstring): registers of arts and crafts workshop work (an Odia silver filigree jeweller's note
to his apprentice, a stained glass evening class's last-one-out card, a weaving studio's loom hire
handbook page, a hand papermaker's notes for the intern in the vat room, a woodturners' club
steward's lock-up card, a willow basketmaker's texts to a course student, a natural-dye studio's
dye-day recipe card, an etching studio's end-of-session clean-down card, a picture framer's work
ticket) and the English of an Odia speaker (the filigree jeweller's note), in room ids beginning
with a letter n-z.
dev 55 was written after dev 54 (beside dev 56, which it never opened; dev 43 known only through
this docstring): registers of hospitality and events work (a conference centre AV technician's
breakout room changeover sheet, a banqueting hall's function sheet with the banqueting manager's notes
for the night porters, a theatre circle bar supervisor's close notes, a youth hostel's reception
handover book, a Bulgarian seasonal manager's campsite shop note for the Saturday cover, a wedding
venue's bridal suite reset card, a hotel housekeeping floor supervisor's room inspection sheet, a
bed-and-breakfast's evening lock-up card for the relief host, a private events caterer's clear-down
sheet) and the English of a Bulgarian speaker (the campsite shop note), in room ids beginning with a
letter a-m.
dev 56 was written after dev 54 (beside dev 55, which it never opened; dev 43 known only through
this docstring): registers of farming, forestry and growing work (a tree surgery yard foreman's saw
shop lock-up notes, a hop drier's oast house night notes, a clearfell harvesting site's welfare cabin
close-down sheet, a Shona speaker's mushroom farm packing room note, a cut-flower farmer's sorting shed
note for her Saturday helper, a Christmas tree farm's netting shed close-up card, an agronomist's crop
walking report, a farm assurance scheme's inspection checklist, a forest harvesting operations site
plan) and the English of a Shona speaker (the packhouse supervisor's note), in room ids beginning with
a letter n-z.
dev 57 was written after dev 56 (beside dev 58, which it never opened; dev 43 known only through
this docstring): registers of health and care work (a dental practice's decontamination room
end-of-day sheet for a trainee dental nurse, a care home's assisted bathroom card for night staff, a
hospital endoscopy unit's recovery end-of-list checklist for the HCA, a Malayali deputy manager's
note for the relief support worker closing a dementia day centre's activities room, a physiotherapy
clinic's hydrotherapy pool close-down list, a midwife-led unit's birth room turnaround card, a
children's hospital ward health play specialist's end-of-day note for the playroom volunteer, a care
home's en-suite check card for the night care assistant's round, a veterinary nurse's in-patient
care sheet written for her own cat's evening sitter) and the English of a Malayalam speaker (the day
centre note), in room ids beginning with a letter a-m.
dev 58 was written after dev 56 (beside dev 57, which it never opened; dev 43 known only through
this docstring): registers of office, legal and administrative work (a Sinhala speaker's accountancy
practice payroll room note for the Saturday trainee, a high-street solicitors' legal secretary's
handover notes for the agency temp, a county records office's search room closing procedure, a
presiding officer's close-of-poll notes for the poll clerks, an advice centre session supervisor's
end-of-session notes for the last volunteer out, a call centre trainer's note to the late team
leader, an office's clear desk policy, a house-sitting agreement's schedule drafted as a contract, a
service level agreement's service description schedule) and the English of a Sinhala speaker (the
payroll note), in room ids beginning with a letter n-z.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest
from reader_sets import (
    DATA,
    check_a_few_factors_and_a_stated_fact,
    check_all_validate,
    check_built_from_json,
    check_fresh_rooms_with_a_new_kind,
    check_ids_new,
    check_mutant_lists_current,
    check_not_templated,
    check_policies,
    check_registers_new,
    check_rewording_changes_only_the_wording,
    check_rewording_names_every_object,
    check_validates,
    rewordings,
)

from logicenveval.benchmark import task_ids


@dataclass(frozen=True)
class DevSet:
    name: str
    suffix: str
    min_rewordings: int
    min_new: int
    #: a new task and a rewording validated in the default run (all are in the slow run)
    samples: tuple[str, str]

    @property
    def reworded(self) -> Path:
        return DATA / self.name / "tasks_reworded"

    @property
    def new(self) -> Path:
        return DATA / self.name / "tasks_new"

    @property
    def earlier(self) -> tuple[str, ...]:
        """The development sets written before it (the held-out sets are never opened here)."""
        n = int(self.name.removeprefix("reader_dev"))
        return ("reader_dev", *(f"reader_dev{k}" for k in range(2, n)))


SETS = (
    DevSet("reader_dev5", "_d5", 16, 8, ("church_hall_clear_up_rota", "kitchen_dish_cleanup_d5")),
    DevSet("reader_dev6", "_d6", 10, 10, ("cloakroom_wedding_run_sheet", "dining_table_clear_d6")),
    DevSet("reader_dev7", "_d7", 6, 10, ("cabin_yacht_logbook", "living_room_toy_boxes_d7")),
    DevSet("reader_dev8", "_d8", 6, 10, ("stateroom_steward_handover", "laundry_drying_rack_d8")),
    DevSet("reader_dev9", "_d9", 4, 8, ("site_office_phone_message_slip", "laundry_sorting_d9")),
    DevSet("reader_dev10", "_d10", 4, 8, ("prep_room_lab_protocol", "kids_room_toy_cleanup_d10")),
    DevSet("reader_dev11", "_d11", 3, 6, ("cellar_dungeon_master", "living_room_plant_care_d11")),
    DevSet("reader_dev12", "_d12", 3, 6, ("greenhouse_grandad_interview", "bathroom_counter_sort_d12")),
    DevSet("reader_dev13", "_d13", 3, 6, ("rec_room_gamebook", "kitchen_fridge_restock_d13")),
    DevSet("reader_dev14", "_d14", 3, 6, ("pool_house_applets", "study_desk_cleanup_d14")),
    DevSet("reader_dev15", "_d15", 3, 6, ("still_room_household_manual", "laundry_drying_rack_d15")),
    DevSet("reader_dev16", "_d16", 3, 6, ("boot_room_letter_from_the_cat", "lamp_or_pillow_fetch_d16")),
    DevSet("reader_dev17", "_d17", 3, 6, ("common_room_management_notice", "living_room_plant_care_d17")),
    DevSet("reader_dev18", "_d18", 3, 6, ("turret_gothic_tale", "multi_room_trash_run_d18")),
    DevSet("reader_dev19", "_d19", 3, 6, ("mahjong_room_auntie_wang", "laundry_drying_rack_d19")),
    DevSet("reader_dev20", "_d20", 3, 6, ("scout_hut_badge_card", "multi_room_lights_off_d20")),
    DevSet("reader_dev21", "_d21", 3, 6, ("bothy_walking_guidebook", "kids_room_toy_cleanup_d21")),
    DevSet("reader_dev22", "_d22", 3, 6, ("wireless_room_blackout_leaflet", "hallway_entry_tidy_d22")),
    DevSet("reader_dev23", "_d23", 3, 6, ("chart_room_shipping_forecast", "dining_table_clear_d23")),
    DevSet("reader_dev24", "_d24", 3, 6, ("outhouse_planning_decision_notice", "clean_living_room_d24")),
    DevSet("reader_dev25", "_d25", 3, 6, ("cycle_store_club_run_sheet", "multi_room_pet_care_d25")),
    DevSet("reader_dev26", "_d26", 3, 6, ("plant_room_eicr_observations", "hallway_coat_and_bag_d26")),
    DevSet("reader_dev27", "_d27", 3, 6, ("chapel_order_of_service", "bathroom_counter_sort_d27")),
    DevSet("reader_dev28", "_d28", 3, 6, ("taproom_pub_close_down_card", "living_room_plant_care_d28")),
    DevSet("reader_dev29", "_d29", 3, 6, ("kiln_room_members_notice", "laundry_drying_rack_d29")),
    DevSet("reader_dev30", "_d30", 3, 6, ("officers_mess_night_order_book", "lamp_or_pillow_fetch_d30")),
    DevSet("reader_dev31", "_d31", 3, 6, ("despatch_bay_pick_list", "bathroom_counter_sort_d31")),
    DevSet("reader_dev32", "_d32", 3, 6, ("tithe_barn_measured_survey_field_notes", "hallway_entry_tidy_d32")),
    DevSet("reader_dev33", "_d33", 3, 6, ("cupola_onboard_short_term_plan", "kitchen_breakfast_prep_d33")),
    DevSet("reader_dev34", "_d34", 3, 6, ("net_loft_skippers_standing_orders", "living_room_toy_boxes_d34")),
    DevSet("reader_dev35", "_d35", 3, 6, ("card_room_prize_cryptic", "laundry_sorting_d35")),
    DevSet("reader_dev36", "_d36", 3, 6, ("strongroom_locksmith_security_survey", "hallway_coat_and_bag_d36")),
    DevSet("reader_dev37", "_d37", 3, 6, ("finds_room_excavation_context_sheet", "lamp_or_pillow_fetch_d37")),
    DevSet("reader_dev38", "_d38", 3, 6, ("tower_cab_atc_position_relief_brief", "laundry_drying_rack_d38")),
    DevSet("reader_dev39", "_d39", 3, 6, ("dapur_malay_auntie_note", "bathroom_counter_sort_d39")),
    DevSet("reader_dev40", "_d40", 3, 6, ("signal_box_signallers_handover", "study_plant_and_light_d40")),
    DevSet("reader_dev41", "_d41", 3, 6, ("lambing_shed_night_lamber_notes", "kitchen_fridge_restock_d41")),
    DevSet("reader_dev42", "_d42", 3, 6, ("porters_lodge_night_handover", "multi_room_trash_run_d42")),
    DevSet("reader_dev43", "_d43", 3, 6, ("chapel_of_rest_viewing_checklist", "lamp_or_pillow_fetch_d43")),
    DevSet("reader_dev44", "_d44", 3, 6, ("service_bay_bike_workshop_job_card", "living_room_toy_boxes_d44")),
    DevSet("reader_dev45", "_d45", 3, 6, ("crew_mess_gozo_ferry_bosun_note", "dining_table_clear_d45")),
    DevSet("reader_dev46", "_d46", 3, 6, ("toddler_room_nursery_closing_handover", "laundry_sorting_d46")),
    DevSet("reader_dev47", "_d47", 3, 6, ("guardhouse_condo_security_relief_note", "multi_room_pet_care_d47")),
    DevSet("reader_dev48", "_d48", 3, 6, ("trade_counter_hardware_shop_owner_note", "study_desk_cleanup_d48")),
    DevSet("reader_dev49", "_d49", 3, 6, ("cider_barn_basque_cider_maker_note", "hallway_entry_tidy_d49")),
    DevSet("reader_dev50", "_d50", 3, 6, ("rasoi_gurdwara_langar_sewa_note", "bathroom_towel_refresh_d50")),
    DevSet("reader_dev51", "_d51", 3, 6, ("foaling_unit_icelandic_stud_night_watch_note", "study_desk_cleanup_d51")),
    DevSet("reader_dev52", "_d52", 3, 6, ("seed_room_seed_bank_lithuanian_technician_note", "multi_room_pet_care_d52")),
    DevSet("reader_dev53", "_d53", 3, 6, ("apparatus_room_telugu_exchange_night_note", "lamp_or_pillow_fetch_d53")),
    DevSet("reader_dev54", "_d54", 3, 6, ("tarakasi_shop_odia_filigree_jeweller_note", "hallway_coat_and_bag_d54")),
    DevSet("reader_dev55", "_d55", 3, 6, ("camp_shop_bulgarian_campsite_shop_note", "multi_room_trash_run_d55")),
    DevSet("reader_dev56", "_d56", 3, 6, ("packing_room_shona_mushroom_farm_note", "dining_table_clear_d56")),
    DevSet("reader_dev57", "_d57", 3, 6, ("activities_room_malayali_day_centre_note", "bathroom_towel_refresh_d57")),
    DevSet("reader_dev58", "_d58", 3, 6, ("payroll_room_sinhala_accountancy_practice_note", "kitchen_fridge_restock_d58")),
)
IDS = [s.name for s in SETS]
ENTRIES = {s.name: rewordings(DATA / s.name) for s in SETS}
ALL_ENTRIES = [(s, e) for s in SETS for e in ENTRIES[s.name]]


@pytest.mark.parametrize("dev", SETS, ids=IDS)
def test_the_set_rewords_builtin_tasks_each_in_its_own_register_and_writes_new_ones(dev: DevSet) -> None:
    entries = ENTRIES[dev.name]
    originals = [str(e["original"]) for e in entries]
    assert len(entries) >= dev.min_rewordings
    assert len(set(originals)) == len(originals)
    assert set(originals) <= set(task_ids())
    registers = [str(e["register"]) for e in entries]
    assert len(set(registers)) == len(registers)
    assert all(str(e["id"]) == f"{e['original']}{dev.suffix}" for e in entries)
    assert len(task_ids(dev.new)) >= dev.min_new


def test_dev5_rewords_every_builtin_task_the_first_development_set_leaves_out() -> None:
    """Development then covers all 25 built-in descriptions, not only the first set's twelve."""
    first = {str(e["original"]) for e in rewordings(DATA / "reader_dev")}
    assert set(task_ids()) - first <= {str(e["original"]) for e in ENTRIES["reader_dev5"]}


@pytest.mark.parametrize("dev", SETS, ids=IDS)
def test_no_register_repeats_one_of_the_earlier_development_sets(dev: DevSet) -> None:
    check_registers_new(ENTRIES[dev.name], dev.earlier)


@pytest.mark.parametrize("dev", SETS, ids=IDS)
def test_ids_do_not_collide_with_the_builtin_tasks_or_the_earlier_development_sets(dev: DevSet) -> None:
    check_ids_new((dev.reworded, dev.new), dev.earlier)


@pytest.mark.parametrize("dev", SETS, ids=IDS)
def test_reworded_folders_are_built_from_the_json(dev: DevSet, tmp_path: Path) -> None:
    check_built_from_json(dev.name, ENTRIES[dev.name], dev.reworded, tmp_path)


@pytest.mark.parametrize(("dev", "entry"), ALL_ENTRIES, ids=[str(e["id"]) for _, e in ALL_ENTRIES])
def test_a_rewording_changes_only_the_wording(dev: DevSet, entry: dict[str, Any]) -> None:
    check_rewording_changes_only_the_wording(entry, dev.reworded)


@pytest.mark.parametrize(("dev", "entry"), ALL_ENTRIES, ids=[str(e["id"]) for _, e in ALL_ENTRIES])
def test_a_rewording_still_names_every_object_its_original_names(dev: DevSet, entry: dict[str, Any]) -> None:
    check_rewording_names_every_object(entry)


@pytest.mark.parametrize("dev", SETS, ids=IDS)
def test_new_tasks_are_in_fresh_rooms_with_a_kind_no_builtin_task_uses(dev: DevSet) -> None:
    check_fresh_rooms_with_a_new_kind(dev.new, dev.earlier)


@pytest.mark.parametrize("dev", SETS, ids=IDS)
def test_new_tasks_have_a_few_independent_factors_and_a_stated_fact(dev: DevSet) -> None:
    check_a_few_factors_and_a_stated_fact(dev.new, min_objects=3)


@pytest.mark.parametrize("dev", SETS, ids=IDS)
def test_new_tasks_are_not_written_in_the_benchmark_template(dev: DevSet) -> None:
    check_not_templated(dev.new, breaks=r"[.!?\n]")


@pytest.mark.parametrize("dev", SETS, ids=IDS)
def test_every_task_ships_its_four_policies_and_a_current_mutant_list(dev: DevSet) -> None:
    check_policies((dev.reworded, dev.new))
    check_mutant_lists_current((dev.reworded, dev.new))


@pytest.mark.parametrize(("dev", "kind"), [(s, k) for s in SETS for k in ("new", "reworded")],
                         ids=[f"{s.name}-{k}" for s in SETS for k in ("new", "reworded")])
def test_a_sample_task_of_each_kind_validates(dev: DevSet, kind: str) -> None:
    folder, task_id = (dev.new, dev.samples[0]) if kind == "new" else (dev.reworded, dev.samples[1])
    check_validates(folder, task_id)


@pytest.mark.slow
@pytest.mark.parametrize(("dev", "kind"), [(s, k) for s in SETS for k in ("new", "reworded")],
                         ids=[f"{s.name}-{k}" for s in SETS for k in ("new", "reworded")])
def test_every_task_validates(dev: DevSet, kind: str) -> None:
    check_all_validate(dev.new if kind == "new" else dev.reworded)
