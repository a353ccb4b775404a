"""The query language's grammar (lark, LALR).

Edit it here, then run `python scripts/make_query_parser.py` to regenerate
`_query_parser.py`; a test fails while the two disagree.
"""

GRAMMAR = r"""
?start: or_expr
?or_expr: and_expr (_OR and_expr)*
?and_expr: atom (_AND atom)*
?atom: "(" or_expr ")"
     | comparison
comparison: field OP value
field: NAME ("." NAME)*
value: NUMBER UNIT?   -> number
     | NAME           -> word
     | STRING         -> quoted
_OR.3: /or\b/i
_AND.3: /and\b/i
OP: "<=" | ">=" | "!=" | "<>" | "<" | ">" | "=" | "≤" | "≥" | "≠"
NAME.2: /[A-Za-z_][A-Za-z0-9_]*/
STRING: /'[^']*'|"[^"]*"/
NUMBER: /[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?/
UNIT: /(ft|lbf?|N|n)[-·*]?(lbf?|lbs|m|ft)\b|deg\/s|rad\/s|°\/s|[A-Za-z°"]+/
%import common.WS
%ignore WS
"""
