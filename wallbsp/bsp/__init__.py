"""wallbsp.bsp"""
