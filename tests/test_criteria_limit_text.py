"""A value against its limit in text (the exercise's log, the viewer's alarm banner and criteria panel, the
assessment table): a value above its limit never reads as the limit (not "ALARM roll: 4 above the limit 4")."""

import dataclasses

from marinesim.cli.assess import table
from marinesim.criteria.monitor import Level, value_and_limit
from marinesim.session.exercise import Alarm, Assessment, CriterionResult


def test_a_value_just_above_its_limit_reads_differently_from_it():
    """Enough digits, up to 6, to tell a value from its limit; three where three do (else the table and banners
    would fill with digits nobody needs); the same text for a value at its limit."""
    assert value_and_limit(4.004, 4.0) == ("4.004", "4")
    assert value_and_limit(4.04, 4.0) == ("4.04", "4")
    assert value_and_limit(3.00001, 3.0) == ("3.00001", "3")
    assert value_and_limit(0.0012345, 0.001) == ("0.00123", "0.001")
    assert value_and_limit(12.3456, 3.0) == ("12.3", "3")
    assert value_and_limit(2.5, 2.5) == ("2.5", "2.5")


def test_the_log_line_and_the_assessment_table_show_the_digits_that_differ():
    """The alarm's log line and the table's worst and limit columns: 4.004 against 4, not 4 against 4."""
    alarm = Alarm(0, "roll", raised_s=12.0, value=4.004, limit=4.0)
    assert alarm.line().endswith("ALARM roll: 4.004 above the limit 4")
    criterion = CriterionResult(name="roll", point=None, quantity="roll_max_deg", unit="deg", window_s=60.0,
                                value=4.004, value_at_s=12.0, limit=4.0, caution=0.8, exceeded=True,
                                time_exceeded_s=3.0, first_exceeded_s=12.0, level=Level.EXCEEDED, judged=True)
    settling = dataclasses.replace(criterion, name="pitch", value=None, level=Level.SETTLING)
    result = Assessment(scenario="s.toml", seed=1, duration_s=60.0, planned_s=60.0, complete=True, dt_s=0.1,
                        criteria=[criterion, settling], events=[], alarms=[], verdict="exceeded")
    rows = [line.split() for line in table(result)[2:4]]
    assert rows[0][:4] == ["roll", "4.004", "4", "deg"] and rows[1][:4] == ["pitch", "settling", "4", "deg"]
