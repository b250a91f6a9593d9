"""The results tables of the studies, one module a study (studies/<name>/ holds its page and CSVs):
each module names its PAGE (from the repository root) and its TABLES, {name: builder}, where a
builder takes the study's folder and returns the table's markdown. post/tables.py finds them here."""
