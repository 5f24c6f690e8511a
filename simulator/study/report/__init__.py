"""What a study writes: CSVs, JSON, heat maps over the room's plan, and report.html."""
