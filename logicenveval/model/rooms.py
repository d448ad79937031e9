"""Room ids and room types.

Tasks name rooms by id (`living_room`); EnvSpecs give each room a type in AI2-THOR style
(`LivingRoom`). `in_room(r, x)` accepts either, so both spellings are mapped here.
"""

from __future__ import annotations

import re

ROOM_TYPES: tuple[str, ...] = (
    "LivingRoom",
    "Kitchen",
    "Bedroom",
    "Bathroom",
    "Study",
    "Hallway",
    "LaundryRoom",
    "DiningRoom",
    "KidsRoom",
    "Garage",
    "Balcony",
    "Office",
    "Pantry",
    "Entryway",
)

_ALIASES = {
    "lounge": "LivingRoom",
    "sitting_room": "LivingRoom",
    "den": "LivingRoom",
    "bed_room": "Bedroom",
    "master_bedroom": "Bedroom",
    "guest_bedroom": "Bedroom",
    "nursery": "KidsRoom",
    "childrens_room": "KidsRoom",
    "kids_room": "KidsRoom",
    "restroom": "Bathroom",
    "toilet": "Bathroom",
    "washroom": "Bathroom",
    "corridor": "Hallway",
    "hall": "Hallway",
    "laundry": "LaundryRoom",
    "utility_room": "LaundryRoom",
    "home_office": "Study",
    "office": "Office",
    "library": "Study",
    "foyer": "Entryway",
    "entrance": "Entryway",
}


def _snake(name: str) -> str:
    return re.sub(r"(?<!^)(?=[A-Z])", "_", name).lower()


_BY_SNAKE = {_snake(t): t for t in ROOM_TYPES}


def room_type_of(room_id: str) -> str:
    """Best room type for a room id: `living_room` -> `LivingRoom`, `bedroom_2` -> `Bedroom`;
    `LivingRoom` for an id that names no known type ("fitness_room")."""
    return known_room_type(room_id) or "LivingRoom"


def known_room_type(room_id: str) -> str | None:
    """The room type a room id names (`room_type_of`), or None when it names none: then the
    type `room_type_of` falls back on is a guess, no evidence of what the room holds."""
    if room_id in ROOM_TYPES:
        return room_id
    key = re.sub(r"_?\d+$", "", room_id.lower())
    if key in _BY_SNAKE:
        return _BY_SNAKE[key]
    if key in _ALIASES:
        return _ALIASES[key]
    for snake, rtype in sorted(_BY_SNAKE.items(), key=lambda kv: -len(kv[0])):
        if snake in key:
            return rtype
    for alias, rtype in _ALIASES.items():
        if alias in key:
            return rtype
    return None


def is_room_type(name: str) -> bool:
    return name in ROOM_TYPES
