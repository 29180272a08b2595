"""The level editor's window (``wallbsp edit``): a pygame map view over the model in
``wallbsp.edit``, with Eureka's keys and mouse habits, the compiler's tree drawn live, a
3-D preview and play from the mouse (docs/editor.md)."""
