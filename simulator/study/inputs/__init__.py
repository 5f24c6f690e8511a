"""A study's inputs: candidate sensor sets, scenarios and trace groups, the sun, the skies."""
