"""simulator.memo.Kept, the bounded store behind the warm-run caches: the least recently used
entry goes first once there are more than max_entries, or more than max_size in all; an entry
its validity check refuses is dropped."""

from simulator.memo import Kept


def test_least_recently_used_goes_first_past_the_entry_bound():
    k = Kept(2)
    k.put("a", 1)
    k.put("b", 2)
    assert k.get("a") == 1  # a is now the most recently used
    k.put("c", 3)
    assert len(k) == 2 and k.get("b") is None and k.get("a") == 1 and k.get("c") == 3


def test_sizes_add_up_to_the_size_bound():
    k = Kept(10, max_size=100)
    k.put("a", "A", size=60)
    k.put("b", "B", size=30)
    k.put("c", "C", size=20)  # 110 in all: a, the oldest, goes
    assert k.get("a") is None and k.get("b") == "B" and k.get("c") == "C"
    k.put("b", "B2", size=90)  # replacing b: 110 with c, so c (now the oldest) goes
    assert k.get("c") is None and k.get("b") == "B2" and len(k) == 1


def test_an_invalid_entry_is_dropped_and_clear_forgets_all():
    k = Kept(4)
    k.put("a", 1)
    k.put("b", 2)
    assert k.get("a", valid=lambda v: v > 5) is None and len(k) == 1
    k.clear()
    assert len(k) == 0 and k.get("b") is None
